#include "hikari/shading/textures/checker_texture.h"

#include <cmath>

#include <gtest/gtest.h>

#include "../../support/test_isa16.h"

namespace hikari {
namespace {

using testing::k_lanes16;
using testing::TestIsa16;
using Floats16 = LaneFloat<TestIsa16>;

TEST(CheckerTexture, FloorParityIsTheParityOfFloor) {
    const float values[] = {
        -2.5f, -2.0f,        -1e-7f,      -0.0f, 0.0f,   1e-7f,         0.999999f,      1.0f,
        3.5f,  -16777217.0f, 16777216.0f, 1e12f, -1e12f, 2147483520.0f, -2147483648.0f, 7.0f};
    float lanes[k_lanes16];
    for (int i = 0; i < k_lanes16; ++i) lanes[i] = values[i];
    const LaneInt<TestIsa16> packed = floor_parity(Floats16::load(lanes));
    for (int i = 0; i < k_lanes16; ++i) {
        const auto floor = static_cast<long long>(std::floor(static_cast<double>(values[i])));
        const int32_t want = static_cast<int32_t>(floor & 1);
        EXPECT_EQ(floor_parity(values[i]), want) << values[i];
        EXPECT_EQ(packed[i], want) << values[i];
    }
}

TEST(CheckerTexture, CellsAlternateAndOffsetMovesThePattern) {
    CheckerTexture t;
    t.size = 0.5f;
    t.color_a = Vec3(1.0f);
    t.color_b = Vec3(0.0f);
    SurfacePoint<float> p;
    p.position = {0.25f, 0.25f, 0.25f};
    EXPECT_EQ(texture_colour(t, p), Vec3(1.0f));
    p.position.x += 0.5f;
    EXPECT_EQ(texture_colour(t, p), Vec3(0.0f));
    t.offset = {0.5f, 0.0f, 0.0f};
    EXPECT_EQ(texture_colour(t, p), Vec3(1.0f));
}

TEST(CheckerTexture, BoxFilterAveragesTheCellsUnderTheFootprint) {
    // The filtered wave is the mean of the sharp one over the box, by brute force.
    for (const float x : {0.1f, 0.5f, 0.97f, 1.3f, -2.6f, 40.25f})
        for (const float w : {0.05f, 0.4f, 1.0f, 2.7f}) {
            double mean = 0;
            constexpr int n = 20000;
            for (int k = 0; k < n; ++k) {
                const float t = x - 0.5f * w + w * (static_cast<float>(k) + 0.5f) / n;
                mean += floor_parity(t) != 0 ? -1.0 : 1.0;
            }
            EXPECT_NEAR(filtered_square_wave(x, w), mean / n, 2e-3) << x << " " << w;
        }
    // Inside one cell, exactly the cell; over many cells, the mean of the two colours.
    EXPECT_EQ(filtered_square_wave(0.5f, 0.2f), 1.0f);
    EXPECT_EQ(filtered_square_wave(1.5f, 0.2f), -1.0f);
    EXPECT_NEAR(filtered_square_wave(0.3f, 1000.0f), 0.0f, 2e-3f);
    CheckerTexture t;
    t.color_a = Vec3(1.0f);
    t.color_b = Vec3(0.0f);
    SurfacePoint<float> far_off;  // a ground plane's pixel spanning 50 cells in x and z
    far_off.position = {0.25f, 0.5f, 0.75f};
    far_off.dp_dx = {50.0f, 0.0f, 0.0f};
    far_off.dp_dy = {0.0f, 0.0f, 50.0f};
    EXPECT_NEAR(texture_colour(t, far_off).x, 0.5f, 0.02f);
}

}  // namespace
}  // namespace hikari
