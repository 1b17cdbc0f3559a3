#include "hikari/raster/half_space.h"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

namespace hikari {
namespace {

ScreenTriangle screen_triangle(Vec3 a, Vec3 b, Vec3 c) {
    return {{ScreenVertex{a, 1}, ScreenVertex{b, 1}, ScreenVertex{c, 1}}, 0};
}

/// Counts how often each pixel of a w × h image is covered by the fan (centre, ring[i],
/// ring[i + 1]) around a closed ring.
std::vector<int> coverage_of_fan(Vec3 centre, const std::vector<Vec3>& ring, int w, int h) {
    std::vector<int> count(static_cast<size_t>(w) * h, 0);
    for (size_t i = 0; i < ring.size(); ++i) {
        HalfSpaceTriangle t;
        if (!setup_half_space(screen_triangle(centre, ring[i], ring[(i + 1) % ring.size()]), w, h,
                              t))
            continue;
        for_each_covered_pixel(t, 0, 0, w, h,
                               [&](int x, int y, float, float, float) { ++count[y * w + x]; });
    }
    return count;
}

TEST(HalfSpace, FanCoveringSquareWritesEachPixelExactlyOnce) {
    // Square [8, 40]²; ring points at integer positions, centre on a pixel centre so that many
    // edges run exactly through pixel centres.
    std::vector<Vec3> ring;
    for (int k = 0; k < 32; k += 4) ring.push_back({8.0f + k, 8, 0});
    for (int k = 0; k < 32; k += 4) ring.push_back({40, 8.0f + k, 0});
    for (int k = 0; k < 32; k += 4) ring.push_back({40.0f - k, 40, 0});
    for (int k = 0; k < 32; k += 4) ring.push_back({8, 40.0f - k, 0});
    for (const Vec3 centre :
         {Vec3{24.5f, 24.5f, 0}, Vec3{17.5f, 30.5f, 0}, Vec3{20.0f, 21.0f, 0}}) {
        const std::vector<int> count = coverage_of_fan(centre, ring, 48, 48);
        for (int y = 0; y < 48; ++y)
            for (int x = 0; x < 48; ++x) {
                const bool inside = x >= 8 && x < 40 && y >= 8 && y < 40;
                ASSERT_EQ(count[y * 48 + x], inside ? 1 : 0) << "pixel " << x << ", " << y;
            }
    }
}

TEST(HalfSpace, SharedEdgesOfTriangleFanNeverDoubleCover) {
    // A regular 37-gon fan about an off-grid centre: pixels are covered once or not at all.
    std::vector<Vec3> ring;
    for (int k = 0; k < 37; ++k) {
        const float a = 2 * std::numbers::pi_v<float> * k / 37;
        ring.push_back({32.5f + 20 * std::cos(a), 32.5f + 20 * std::sin(a), 0});
    }
    const std::vector<int> count = coverage_of_fan({32.5f, 32.5f, 0}, ring, 64, 64);
    int covered = 0;
    for (int c : count) {
        ASSERT_LE(c, 1);
        covered += c;
    }
    EXPECT_NEAR(covered, std::numbers::pi * 400, 60);
}

TEST(HalfSpace, TopAndLeftEdgesOwnTheirPixelCentres) {
    // Square [2.5, 4.5]² split by a diagonal: centres on its top and left edges are in, on its
    // bottom and right edges out.
    std::vector<int> count(64, 0);
    for (const ScreenTriangle& st :
         {screen_triangle({2.5f, 2.5f, 0}, {4.5f, 2.5f, 0}, {4.5f, 4.5f, 0}),
          screen_triangle({2.5f, 2.5f, 0}, {4.5f, 4.5f, 0}, {2.5f, 4.5f, 0})}) {
        HalfSpaceTriangle t;
        ASSERT_TRUE(setup_half_space(st, 8, 8, t));
        for_each_covered_pixel(t, 0, 0, 8, 8,
                               [&](int x, int y, float, float, float) { ++count[y * 8 + x]; });
    }
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            EXPECT_EQ(count[y * 8 + x], (x == 2 || x == 3) && (y == 2 || y == 3) ? 1 : 0)
                << x << ", " << y;
}

TEST(HalfSpace, BarycentricsInterpolateVertices) {
    HalfSpaceTriangle t;
    ASSERT_TRUE(setup_half_space(screen_triangle({0, 0, 0}, {16, 0, 0}, {0, 16, 0}), 16, 16, t));
    for_each_covered_pixel(t, 0, 0, 16, 16, [&](int x, int y, float b0, float b1, float b2) {
        EXPECT_NEAR(b0 + b1 + b2, 1.0f, 1e-5f);
        const float px = b0 * t.x[0] + b1 * t.x[1] + b2 * t.x[2];
        const float py = b0 * t.y[0] + b1 * t.y[1] + b2 * t.y[2];
        EXPECT_NEAR(px / k_subpixel_one, x + 0.5f, 1e-3f);
        EXPECT_NEAR(py / k_subpixel_one, y + 0.5f, 1e-3f);
    });
}

}  // namespace
}  // namespace hikari
