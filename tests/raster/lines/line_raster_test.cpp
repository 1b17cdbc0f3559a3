#include "hikari/raster/lines/line_raster.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "hikari/core/color.h"

namespace hikari {
namespace {

LineDrawing drawing(int w, int h, float width) {
    LineDrawing d;
    d.width = w;
    d.height = h;
    d.line_width = width;
    d.camera.eye = Vec3(0, 0, 0);
    return d;
}

LineSegment segment(Vec2 a, Vec2 b, Vec3 color = Vec3(1.0f)) {
    LineSegment s;
    s.a = a;
    s.b = b;
    s.world_a = Vec3(a.x, a.y, -10);
    s.world_b = Vec3(b.x, b.y, -10);
    s.color = color;
    return s;
}

/// The sum of the pixels' sRGB-encoded red: for a white line on black, composited in sRGB, the
/// sum of its coverages.
double coverage_sum(const Framebuffer& fb) {
    double sum = 0;
    for (const Vec3& c : fb.film.linear().pixels) sum += linear_to_srgb(c.x);
    return sum;
}

TEST(LineRaster, CoverageIsTheStrokeAreaInEveryDirection) {
    // On black, a white line's pixel values sum to its area, width × length, at any angle.
    for (const float width : {0.5f, 1.0f, 3.0f})
        for (const float angle : {0.0f, 0.3f, 0.785398f, 1.2f}) {
            LineDrawing d = drawing(64, 64, width);
            const float len = 40.0f;
            d.segments.push_back(segment(
                {12.3f, 11.7f}, {12.3f + len * std::cos(angle), 11.7f + len * std::sin(angle)}));
            const Framebuffer fb = rasterize_lines(d, Film(64, 64, FilmFormat::linear), false);
            EXPECT_NEAR(coverage_sum(fb), width * len, 0.02 * width * len)
                << "width " << width << ", angle " << angle;
        }
}

TEST(LineRaster, AxisAlignedCoverageIsExact) {
    EXPECT_FLOAT_EQ(line_coverage(0.0f, 5.0f, 10.0f, 1.0f, 1, 0), 1.0f);
    EXPECT_FLOAT_EQ(line_coverage(0.5f, 5.0f, 10.0f, 1.0f, 0, 1), 0.5f);
    EXPECT_FLOAT_EQ(line_coverage(0.25f, 0.0f, 10.0f, 1.0f, 1, 0),
                    0.375f);  // 3/4 across, half along
    EXPECT_FLOAT_EQ(line_coverage(2.0f, 5.0f, 10.0f, 1.0f, -1, 0), 0.0f);
    EXPECT_FLOAT_EQ(line_coverage(0.0f, 5.0f, 10.0f, 0.5f, 0, -1), 0.5f);
    // At 45°, a pixel centred on a wide line's axis is covered whole; on its edge, half.
    const float r = std::sqrt(0.5f);
    EXPECT_NEAR(line_coverage(0.0f, 5.0f, 10.0f, 2.0f, r, r), 1.0f, 1e-6f);
    EXPECT_NEAR(line_coverage(1.0f, 5.0f, 10.0f, 2.0f, r, r), 0.5f, 1e-6f);
}

TEST(LineRaster, OcclusionHidesEachSegmentForItself) {
    // Two segments on the same pixels (a sphere's back and front equator seen edge-on), the
    // hidden one (some 200 units away) drawn last, over surfaces 30 units from the eye: the
    // front one (at most 25 away) shows on every pixel of its row, the back one on none.
    LineDrawing d = drawing(20, 20, 1.0f);
    d.segments.push_back(segment({0, 10.5f}, {20, 10.5f}));
    LineSegment behind = segment({0, 10.5f}, {20, 10.5f}, Vec3(1, 0, 0));
    behind.world_a.z = behind.world_b.z = -200;
    d.segments.push_back(behind);
    const std::vector<float> surface(20 * 20, 30.0f);
    const Framebuffer fb =
        rasterize_lines(d, Film(20, 20, FilmFormat::linear), false, {surface, 0.01f});
    for (int x = 0; x < 20; ++x) EXPECT_EQ(fb.film.linear().pixels[10 * 20 + x], Vec3(1.0f)) << x;
    // Without the front segment nothing is drawn.
    d.segments.erase(d.segments.begin());
    const Framebuffer hidden =
        rasterize_lines(d, Film(20, 20, FilmFormat::linear), false, {surface, 0.01f});
    EXPECT_DOUBLE_EQ(coverage_sum(hidden), 0.0);
}

TEST(LineRaster, LaterSegmentsGoOverEarlierOnesInSrgb) {
    LineDrawing d = drawing(20, 20, 2.0f);
    d.background = Vec3(0.0f, 1.0f, 0.0f);
    d.segments.push_back(segment({0, 10}, {20, 10}, Vec3(1, 0, 0)));      // red, rows 9 and 10
    d.segments.push_back(segment({10, 0}, {10, 20}, Vec3(0, 0, 1)));      // blue, columns 9, 10
    d.segments.push_back(segment({0, 3.5f}, {20, 3.5f}, Vec3(1, 0, 0)));  // half of rows 2, 4
    const Framebuffer fb = rasterize_lines(d, Film(20, 20, FilmFormat::linear), false);
    const auto& px = fb.film.linear().pixels;
    EXPECT_EQ(px[10 * 20 + 10], Vec3(0, 0, 1));  // blue over red where they cross
    EXPECT_EQ(px[10 * 20 + 3], Vec3(1, 0, 0));
    EXPECT_EQ(px[15 * 20 + 3], Vec3(0, 1, 0));  // untouched: the background, exactly
    // Half covered: halfway between green and red in sRGB-encoded values.
    const Vec3 half = px[2 * 20 + 15];
    EXPECT_NEAR(linear_to_srgb(half.x), 0.5f, 1e-5f);
    EXPECT_NEAR(linear_to_srgb(half.y), 0.5f, 1e-5f);
    EXPECT_NEAR(half.z, 0.0f, 1e-6f);
}

TEST(LineRaster, ResultDoesNotDependOnThreadCount) {
    LineDrawing d = drawing(97, 83, 2.0f);
    for (int k = 0; k < 200; ++k)
        d.segments.push_back(segment({float(k % 97), float(k * 7 % 83)},
                                     {float(k * 13 % 97), float(k * 3 % 83)},
                                     Vec3(float(k % 5) / 5, 0.5f, 1.0f)));
    Framebuffer one;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = rasterize_lines(d, Film(97, 83, FilmFormat::linear), true);
    }
    const Framebuffer all = rasterize_lines(d, Film(97, 83, FilmFormat::linear), true);
    EXPECT_EQ(one.film.linear().pixels, all.film.linear().pixels);
    EXPECT_EQ(one.depth, all.depth);
}

}  // namespace
}  // namespace hikari
