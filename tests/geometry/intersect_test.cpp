#include "hikari/geometry/intersect.h"

#include <cmath>

#include <gtest/gtest.h>

namespace hikari {
namespace {

const Interval k_forward{0.0f, k_infinity};

TEST(RaySphere, HitsNearSideFirst) {
    const float t = intersect_sphere({{0, 0, 0}, {0, 0, -1}}, {0, 0, -3}, 1, k_forward);
    EXPECT_FLOAT_EQ(t, 2.0f);
}

TEST(RaySphere, Misses) {
    EXPECT_TRUE(std::isnan(intersect_sphere({{0, 0, 0}, {0, 1, 0}}, {0, 0, -3}, 1, k_forward)));
    EXPECT_TRUE(
        std::isnan(intersect_sphere({{0, 1.001f, 0}, {0, 0, -1}}, {0, 0, -3}, 1, k_forward)));
}

TEST(RaySphere, TangentRayTouchesOnce) {
    const float t = intersect_sphere({{0, 1, 0}, {0, 0, -1}}, {0, 0, -3}, 1, k_forward);
    EXPECT_NEAR(t, 3.0f, 1e-3f);
}

TEST(RaySphere, FromInsideHitsFarSide) {
    const float t = intersect_sphere({{0, 0, -3}, {1, 0, 0}}, {0, 0, -3}, 2, k_forward);
    EXPECT_FLOAT_EQ(t, 2.0f);
}

TEST(RaySphere, SphereBehindRayIsMissed) {
    EXPECT_TRUE(std::isnan(intersect_sphere({{0, 0, 0}, {0, 0, 1}}, {0, 0, -3}, 1, k_forward)));
}

TEST(RaySphere, RespectsIntervalMax) {
    EXPECT_TRUE(std::isnan(intersect_sphere({{0, 0, 0}, {0, 0, -1}}, {0, 0, -3}, 1, {0, 1.5f})));
}

TEST(RaySphere, FarAwaySphereStaysAccurate) {
    // The naive discriminant B² − 4AC cancels badly here; the stable form does not.
    const float t = intersect_sphere({{0, 0, 0}, {0, 0, -1}}, {0, 0, -10000}, 1, k_forward);
    EXPECT_NEAR(t, 9999.0f, 1e-3f);
    EXPECT_FALSE(
        std::isnan(intersect_sphere({{0, 0.999f, 0}, {0, 0, -1}}, {0, 0, -10000}, 1, k_forward)));
}

TEST(RayPlane, HitsAndMisses) {
    EXPECT_FLOAT_EQ(intersect_plane({{0, 2, 0}, {0, -1, 0}}, {0, 0, 0}, {0, 1, 0}, k_forward),
                    2.0f);
    // From below a two-sided plane is hit too.
    EXPECT_FLOAT_EQ(intersect_plane({{0, -2, 0}, {0, 1, 0}}, {0, 0, 0}, {0, 1, 0}, k_forward),
                    2.0f);
    EXPECT_TRUE(
        std::isnan(intersect_plane({{0, 2, 0}, {1, 0, 0}}, {0, 0, 0}, {0, 1, 0}, k_forward)));
    EXPECT_TRUE(
        std::isnan(intersect_plane({{0, 2, 0}, {0, 1, 0}}, {0, 0, 0}, {0, 1, 0}, k_forward)));
}

}  // namespace
}  // namespace hikari
