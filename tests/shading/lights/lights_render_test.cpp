// Area and environment lights rendered whole, by the ray tracer and the rasterizer: the limits
// the lights must reach (a small far area light is a point light, constant sky light on an
// open plane is kd·π·L), the methods agreeing with each other, soft shadows widening with the
// distance from the occluder, and images independent of the thread count.
#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "../../io/temp_dir.h"
#include "../../raster/raster_test_util.h"

#include "../../support/pi.h"
#include "hikari/integrators/whitted/whitted.h"
#include "hikari/io/images/image_write.h"
#include "hikari/raster/zbuffer.h"

namespace hikari {
namespace {

using testing::k_pi_f;

/// A sphere on a ground of two triangles, seen from the front, lit by `lights` (JSON).
std::string sphere_on_ground(const std::string& lights, int size = 96) {
    return fmt::format(R"({{
      "camera": {{"eye": [0, 2.5, 5], "look_at": [0, 0.5, 0], "fov_y": 45, "width": {0},
                  "height": {0}}},
      "materials": {{"m": {{"ka": [0, 0, 0], "kd": [0.7, 0.7, 0.7], "ks": [0.3, 0.3, 0.3],
                            "shininess": 20}}}},
      "lights": [{1}],
      "objects": [{{"type": "sphere", "center": [0, 0.7, 0], "radius": 0.7, "material": "m"}},
                  {{"type": "triangle", "vertices": [[-5, 0, -5], [-5, 0, 5], [5, 0, 5]], "material": "m"}},
                  {{"type": "triangle", "vertices": [[-5, 0, -5], [5, 0, 5], [5, 0, -5]], "material": "m"}}]}})",
                       size, lights);
}

Framebuffer ray_trace(const Scene& scene, const WhittedSettings& w = {}) {
    return render_whitted(scene, Film(scene.camera), {}, w);
}

Framebuffer rasterize(const Scene& scene, ShadowMode shadows, int samples = 16) {
    RasterSettings r;
    r.shadows = shadows;
    r.light_samples = samples;
    return render_zbuffer(scene, Film(scene.camera), {}, r);
}

TEST(LightsRender, SmallFarAreaLightIsItsPointLight) {
    // A 0.2 x 0.2 light 40 units up: intensity L·A = 400 · 0.04 = 16 toward its axis.
    const Scene area = testing::raster_scene_from(sphere_on_ground(
        R"({"type": "area", "corner": [2.9, 40, 1.9], "edge1": [0.2, 0, 0], "edge2": [0, 0, 0.2],
            "radiance": [400, 400, 400]})"));
    const Scene point = testing::raster_scene_from(sphere_on_ground(
        R"({"type": "point", "position": [3, 40, 2], "intensity": [16, 16, 16]})"));
    EXPECT_GT(testing::psnr(ray_trace(area), ray_trace(point)), 35.0);
    EXPECT_GT(testing::psnr(rasterize(area, ShadowMode::analytic),
                            rasterize(point, ShadowMode::analytic)),
              35.0);
}

TEST(LightsRender, ConstantSkyOnAnOpenPlaneIsKdPiL) {
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0, 3, 4], "look_at": [0, 0, 0], "width": 32, "height": 32},
      "materials": {"m": {"ka": [0, 0, 0], "kd": [0.5, 0.25, 0.125]}},
      "lights": [{"type": "environment", "radiance": [0.4, 0.6, 0.8]}],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "m"}]})");
    const Vec3 expected = Vec3(0.5f, 0.25f, 0.125f) * Vec3(0.4f, 0.6f, 0.8f) * k_pi_f;
    for (const Framebuffer& fb : {ray_trace(scene), rasterize(scene, ShadowMode::map)}) {
        int checked = 0;
        for (size_t i = 0; i < fb.id.size(); ++i) {
            if (fb.id[i] == 0) continue;  // the sky
            ++checked;
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(fb.film.linear().pixels[i][c], expected[c], 0.01f * expected[c]);
        }
        EXPECT_GT(checked, 400);
    }
}

TEST(LightsRender, RaysSeeTheLightsThemselves) {
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0, 0, 0], "look_at": [0, 0, -1], "fov_y": 60, "width": 16, "height": 16},
      "background": [1, 0, 0],
      "lights": [{"type": "area", "corner": [-5, -5, -3], "edge1": [10, 0, 0], "edge2": [0, 5, 0],
                  "radiance": [0.2, 0.3, 0.4]},
                 {"type": "environment", "radiance": [0.9, 0.8, 0.7]}],
      "objects": []})");
    const Framebuffer fb = ray_trace(scene);
    const Image& img = fb.film.linear();
    EXPECT_EQ(img.at(8, 15), Vec3(0.2f, 0.3f, 0.4f));  // below the horizon: the light's face
    EXPECT_EQ(img.at(8, 0), Vec3(0.9f, 0.8f, 0.7f));   // above it: the sky, not the background
    const Framebuffer raster = rasterize(scene, ShadowMode::none);
    EXPECT_EQ(raster.film.linear().at(8, 15), Vec3(0.2f, 0.3f, 0.4f));
    EXPECT_EQ(raster.film.linear().at(8, 0), Vec3(0.9f, 0.8f, 0.7f));
}

TEST(LightsRender, ImagesDoNotDependOnTheThreadCount) {
    const Scene scene = testing::raster_scene_from(sphere_on_ground(
        R"({"type": "area", "corner": [-0.5, 3, -0.5], "edge1": [1, 0, 0], "edge2": [0, 0, 1],
            "radiance": [5, 5, 5]}, {"type": "environment", "radiance": [0.2, 0.2, 0.3]})",
        48));
    WhittedSettings w;
    w.light_samples = 8;
    const Framebuffer many = ray_trace(scene, w);
    const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    const Framebuffer single = ray_trace(scene, w);
    EXPECT_EQ(many.film.linear().pixels, single.film.linear().pixels);
}

TEST(LightsRender, AnalyticAndManySamplesAgree) {
    const Scene scene = testing::raster_scene_from(sphere_on_ground(
        R"({"type": "area", "corner": [-1, 3, -0.5], "edge1": [2, 0, 0], "edge2": [0, 0, 1],
            "radiance": [3, 3, 3]})"));
    WhittedSettings sampled, analytic;
    sampled.light_samples = 256;
    analytic.light_samples = 256;
    analytic.analytic_area_shadows = true;
    WhittedSettings few = sampled;
    few.light_samples = 4;
    const Framebuffer exact = ray_trace(scene, analytic);
    const double many = testing::psnr(exact, ray_trace(scene, sampled));
    EXPECT_GT(many, 40.0);
    EXPECT_GT(many, testing::psnr(exact, ray_trace(scene, few)) + 6.0);
    // The rasterizer's analytic mode, and its filtered maps, near the ray tracer's.
    EXPECT_GT(testing::psnr(exact, rasterize(scene, ShadowMode::analytic)), 35.0);
    EXPECT_GT(testing::psnr(exact, rasterize(scene, ShadowMode::pcf)), 25.0);
    EXPECT_GT(testing::psnr(exact, rasterize(scene, ShadowMode::pcss)), 25.0);
}

/// Ground pixels (primitive ids 0 and 1) of row `y` in penumbra: lit by between 10% and 90%
/// of what reaches them without shadows.
int penumbra_pixels(const Framebuffer& shadowed, const Framebuffer& open, int y) {
    int n = 0;
    const int width = shadowed.film.linear().width;
    for (int x = 0; x < width; ++x) {
        const size_t i = static_cast<size_t>(y) * width + x;
        if (shadowed.id[i] != 1 && shadowed.id[i] != 2) continue;
        const float v = shadowed.film.linear().pixels[i].y / open.film.linear().pixels[i].y;
        n += v > 0.1f && v < 0.9f;
    }
    return n;
}

TEST(LightsRender, PcssPenumbraWidensWithTheOccludersDistance) {
    // Looking straight down on the ground; a long bar casts its shadow across the image, at two
    // heights: the higher, the wider the penumbra (Fernando 2005), as in the analytic shadow.
    const auto scene_at = [](float height) {
        return testing::raster_scene_from(fmt::format(R"({{
          "camera": {{"eye": [0, 6, 0.001], "look_at": [0, 0, 0], "fov_y": 40, "width": 96,
                      "height": 96}},
          "materials": {{"m": {{"ka": [0, 0, 0], "kd": [0.8, 0.8, 0.8]}}}},
          "lights": [{{"type": "area", "corner": [-0.4, 5, -0.4], "edge1": [0.8, 0, 0],
                       "edge2": [0, 0, 0.8], "radiance": [20, 20, 20]}}],
          "objects": [
            {{"type": "triangle", "vertices": [[-9, 0, -9], [-9, 0, 9], [9, 0, 9]], "material": "m"}},
            {{"type": "triangle", "vertices": [[-9, 0, -9], [9, 0, 9], [9, 0, -9]], "material": "m"}},
            {{"type": "triangle", "vertices": [[-0.3, {0}, -9], [-0.3, {0}, 9], [9, {0}, 9]], "material": "m"}},
            {{"type": "triangle", "vertices": [[-0.3, {0}, -9], [9, {0}, 9], [9, {0}, -9]], "material": "m"}}]}})",
                                                      height));
    };
    const Scene low = scene_at(0.5f), high = scene_at(2.5f);
    for (const ShadowMode mode : {ShadowMode::pcss, ShadowMode::analytic}) {
        const int near =
            penumbra_pixels(rasterize(low, mode), rasterize(low, ShadowMode::none), 48);
        const int far =
            penumbra_pixels(rasterize(high, mode), rasterize(high, ShadowMode::none), 48);
        EXPECT_GE(near, 1);
        EXPECT_GT(far, 2 * near) << "mode " << static_cast<int>(mode);
    }
}

}  // namespace
}  // namespace hikari
