// Depth cueing (Fig 4.1b): the blend toward the cue colour follows the lecture's formula pixel by
// pixel, and the blur grows with distance without smearing near edges.
#include "hikari/frame/depth_cue.h"

#include <cmath>

#include <gtest/gtest.h>

namespace hikari {
namespace {

DepthCue cue(float near, float far, float blur = 0.0f) {
    DepthCue c;
    c.near = near;
    c.far = far;
    c.blur = blur;
    return c;
}

/// A width x 1 framebuffer with the given colours and depths.
Framebuffer strip(const std::vector<Vec3>& colours, const std::vector<float>& depths) {
    const int width = static_cast<int>(colours.size());
    Framebuffer fb(Film(width, 1, FilmFormat::linear), width, 1, true);
    for (int x = 0; x < width; ++x) {
        fb.film.linear().pixels[x] = colours[x];
        fb.depth[x] = depths[x];
    }
    return fb;
}

TEST(DepthCue, WeightIsOneNearZeroFarLinearBetween) {
    const DepthCue c = cue(2.0f, 6.0f);
    EXPECT_EQ(depth_cue_weight(c, 1.0f), 1.0f);
    EXPECT_EQ(depth_cue_weight(c, 2.0f), 1.0f);
    EXPECT_FLOAT_EQ(depth_cue_weight(c, 3.0f), 0.75f);
    EXPECT_FLOAT_EQ(depth_cue_weight(c, 4.0f), 0.5f);
    EXPECT_EQ(depth_cue_weight(c, 6.0f), 0.0f);
    EXPECT_EQ(depth_cue_weight(c, 100.0f), 0.0f);
    EXPECT_EQ(depth_cue_weight(c, INFINITY), 0.0f);  // nothing seen: only the cue colour
    EXPECT_EQ(depth_cue_blur_radius(cue(2.0f, 6.0f, 8.0f), 4.0f), 4.0f);
    EXPECT_EQ(depth_cue_blur_radius(cue(2.0f, 6.0f, 8.0f), 1.0f), 0.0f);
}

TEST(DepthCue, EveryPixelIsBlendedByItsOwnDepth) {
    const std::vector<Vec3> colours = {Vec3(1.0f), {0.2f, 0.4f, 0.8f}, Vec3(0.5f), Vec3(0.9f)};
    const std::vector<float> depths = {1.0f, 3.0f, 5.5f, INFINITY};
    Framebuffer fb = strip(colours, depths);
    DepthCue c = cue(2.0f, 6.0f);
    c.color = Vec3(0.1f, 0.2f, 0.3f);
    apply_depth_cue(c, Vec3(0.7f), fb);
    for (size_t i = 0; i < colours.size(); ++i) {
        const float w = std::clamp((6.0f - depths[i]) / 4.0f, 0.0f, 1.0f);
        for (int a = 0; a < 3; ++a)
            EXPECT_NEAR(fb.film.linear().pixels[i][a], w * colours[i][a] + (1 - w) * (*c.color)[a],
                        1e-6f)
                << "pixel " << i;
    }
}

TEST(DepthCue, CueColourDefaultsToTheBackground) {
    Framebuffer fb = strip({Vec3(1.0f)}, {10.0f});
    apply_depth_cue(cue(0.0f, 5.0f), Vec3(0.25f, 0.5f, 0.75f), fb);
    EXPECT_EQ(fb.film.linear().pixels[0], Vec3(0.25f, 0.5f, 0.75f));
}

TEST(DepthCue, BlurGrowsWithDistanceAndKeepsNearEdgesSharp) {
    // A near white object (depth 1) left of a far striped wall (depth 9, black and white).
    std::vector<Vec3> colours;
    std::vector<float> depths;
    for (int x = 0; x < 12; ++x) {
        colours.push_back(x < 4 ? Vec3(1.0f) : Vec3(x % 2 == 0 ? 1.0f : 0.0f));
        depths.push_back(x < 4 ? 1.0f : 9.0f);
    }
    Framebuffer fb = strip(colours, depths);
    DepthCue c = cue(0.0f, 100.0f, 20.0f);  // radius 0.2 px at the object, 1.8 px at the wall
    c.color = Vec3(0.0f);
    apply_depth_cue(c, Vec3(0.0f), fb);
    const Image& out = fb.film.linear();
    for (int x = 0; x < 4; ++x)  // near: sharp, only dimmed by the blend
        EXPECT_NEAR(out.pixels[x].x, depth_cue_weight(c, 1.0f), 1e-6f) << x;
    // The wall is averaged over its own pixels only: the white object does not bleed into it.
    const float wall = depth_cue_weight(c, 9.0f);
    EXPECT_NEAR(out.pixels[4].x, wall * (1.0f + 0.0f) / 2.0f, 1e-6f);  // x 4 and 5 only
    for (int x = 5; x < 11; ++x)  // three wall pixels each: the even ones are white
        EXPECT_NEAR(out.pixels[x].x, wall * (x % 2 == 0 ? 1.0f : 2.0f) / 3.0f, 1e-6f) << x;
}

TEST(DepthCue, RefusesAFramebufferWithoutDepth) {
    Framebuffer fb(Film(2, 1, FilmFormat::linear), 2, 1, false);
    EXPECT_THROW(apply_depth_cue(cue(0.0f, 1.0f), Vec3(0.0f), fb), std::logic_error);
}

}  // namespace
}  // namespace hikari

namespace hikari {
namespace {

/// A width x height framebuffer at depth `depth`, colour varying across it.
Framebuffer gradient(int width, int height, float depth) {
    Framebuffer fb(Film(width, height, FilmFormat::linear), width, height, true);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const size_t i = static_cast<size_t>(y) * width + x;
            fb.film.linear().pixels[i] = Vec3(float(x) / width, float(y) / height, 0.5f);
            fb.depth[i] = depth;
        }
    return fb;
}

TEST(DepthCue, BlurRadiiAreClampedToTheImage) {
    // 10^4 and 10^12 pixels both reach past the 50-pixel diagonal: the same picture, finite,
    // every pixel an average of the image's colours (10^12 once overflowed into no blur).
    Framebuffer wide = gradient(40, 30, 10.0f), huge = gradient(40, 30, 10.0f);
    DepthCue c = cue(1.0f, 100.0f, 1e4f);
    apply_depth_cue(c, Vec3(0.0f), wide);
    c.blur = 1e12f;
    apply_depth_cue(c, Vec3(0.0f), huge);
    const Framebuffer sharp = [&] {
        Framebuffer fb = gradient(40, 30, 10.0f);
        apply_depth_cue(cue(1.0f, 100.0f), Vec3(0.0f), fb);
        return fb;
    }();
    const float w = depth_cue_weight(c, 10.0f);
    for (size_t i = 0; i < huge.film.linear().pixels.size(); ++i) {
        EXPECT_EQ(wide.film.linear().pixels[i], huge.film.linear().pixels[i]) << i;
        const Vec3 p = huge.film.linear().pixels[i] / w;
        EXPECT_TRUE(p.x >= 0.0f && p.x < 1.0f && p.y >= 0.0f && p.y < 1.0f) << i;
    }
    // Blurred: the corners move toward the middle's colour.
    EXPECT_GT(huge.film.linear().pixels[0].x, sharp.film.linear().pixels[0].x + 0.1f * w);
}

TEST(DepthCue, AWideBlurOfAFlatImageKeepsItFlat) {
    Framebuffer fb(Film(300, 200, FilmFormat::linear), 300, 200, true);
    for (Vec3& p : fb.film.linear().pixels) p = Vec3(0.25f, 0.5f, 0.75f);
    for (float& d : fb.depth) d = 50.0f;
    apply_depth_cue(cue(0.0f, 100.0f, 1000.0f), Vec3(0.0f), fb);
    for (const Vec3& p : fb.film.linear().pixels) {
        EXPECT_NEAR(p.x, 0.5f * 0.25f, 1e-6f);
        EXPECT_NEAR(p.z, 0.5f * 0.75f, 1e-6f);
    }
}

}  // namespace
}  // namespace hikari
