#include "hikari/raster/line_raster.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

namespace hikari {
namespace {

LineDrawing drawing(int w, int h, float width) {
    LineDrawing d;
    d.width = w;
    d.height = h;
    d.line_width = width;
    d.eye = Vec3(0, 0, 0);
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

double coverage_sum(const Framebuffer& fb) {
    double sum = 0;
    for (const Vec3& c : fb.film.linear().pixels) sum += c.x;
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

TEST(LineRaster, PiecesOfOneLineJoinWithoutASeam) {
    LineDrawing whole = drawing(40, 16, 1.5f), pieces = whole;
    whole.segments.push_back(segment({3.2f, 4.1f}, {35.7f, 11.3f}));
    const float s = 0.37f;
    const Vec2 mid{3.2f + s * (35.7f - 3.2f), 4.1f + s * (11.3f - 4.1f)};
    pieces.segments.push_back(segment({3.2f, 4.1f}, mid));
    pieces.segments.push_back(segment(mid, {35.7f, 11.3f}));
    const Framebuffer a = rasterize_lines(whole, Film(40, 16, FilmFormat::linear), false);
    const Framebuffer b = rasterize_lines(pieces, Film(40, 16, FilmFormat::linear), false);
    for (size_t i = 0; i < a.film.linear().pixels.size(); ++i)
        EXPECT_NEAR(a.film.linear().pixels[i].x, b.film.linear().pixels[i].x, 1e-5f) << i;
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
