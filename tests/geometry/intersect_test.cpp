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

/// The textbook solution, for contrast: |o + t d - c|² = r² expanded in o and c separately,
/// t = -b - sqrt(b² - C) with b = d·o - d·c and C = o·o - 2 o·c + c·c - r². Far from the origin
/// o·o, o·c and c·c are ~2e10 and their float sum loses every digit of C.
float textbook_sphere(const Ray& ray, Vec3 center, float radius) {
    const float b = dot(ray.direction, ray.origin) - dot(ray.direction, center);
    const float c = dot(ray.origin, ray.origin) - 2.0f * dot(ray.origin, center) +
                    dot(center, center) - radius * radius;
    const float discriminant = b * b - c;
    return discriminant < 0.0f ? NAN : -b - std::sqrt(discriminant);
}

/// How far the hit at `t` lies off the sphere, relative to its radius, in double.
double off_sphere(const Ray& ray, float t, Vec3 center, float radius) {
    double d2 = 0;
    for (int a = 0; a < 3; ++a) {
        const double p = double(ray.origin[a]) + double(t) * double(ray.direction[a]);
        d2 += (p - center[a]) * (p - center[a]);
    }
    return std::abs(std::sqrt(d2) - radius) / radius;
}

TEST(RaySphere, StableFarFromTheOrigin) {
    // Haines, Günther & Akenine-Möller 2019 (Ray Tracing Gems ch. 7): a unit sphere 1e5 units
    // out, seen from 10 units away, along oblique and grazing rays.
    const Vec3 center{1e5f, 0.0f, 1e5f};
    int textbook_failures = 0;
    for (float aim : {0.0f, 0.3f, 0.7f, 0.95f}) {
        SCOPED_TRACE(aim);
        const Vec3 origin = center + Vec3(6.0f, 8.0f, 0.0f);  // 10 units away
        const Vec3 target = center + aim * normalize(Vec3(0.0f, 0.6f, 0.8f));
        const Ray ray{origin, normalize(target - origin)};
        const float t = intersect_sphere(ray, center, 1.0f, k_forward);
        ASSERT_FALSE(std::isnan(t));
        EXPECT_LT(off_sphere(ray, t, center, 1.0f), 1e-3);
        const float naive = textbook_sphere(ray, center, 1.0f);
        textbook_failures += std::isnan(naive) || off_sphere(ray, naive, center, 1.0f) > 1e-3;
    }
    EXPECT_GT(textbook_failures, 0);  // the test can tell the two forms apart
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
