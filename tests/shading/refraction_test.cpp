#include "hikari/shading/refraction.h"

#include <cmath>

#include <gtest/gtest.h>

namespace hikari {
namespace {

TEST(Refraction, NormalIncidenceGoesStraightThrough) {
    const auto t = refract({0, 0, -1}, {0, 0, 1}, 1.0f / 1.5f);
    ASSERT_TRUE(t.has_value());
    EXPECT_NEAR(t->z, -1.0f, 1e-6);
}

TEST(Refraction, SnellsLawHolds) {
    const float theta_i = 0.6f;
    const Vec3 d{std::sin(theta_i), 0, -std::cos(theta_i)};
    const auto t = refract(d, {0, 0, 1}, 1.0f / 1.5f);
    ASSERT_TRUE(t.has_value());
    EXPECT_NEAR(1.0f * std::sin(theta_i), 1.5f * t->x, 1e-6);  // sin θ_t = t.x
    EXPECT_NEAR(length(*t), 1.0f, 1e-6);
}

TEST(Refraction, ParallelSlabRestoresDirection) {
    // Into glass through the top face and out through the parallel bottom face: the ray leaves
    // parallel to how it came in.
    const Vec3 d = normalize(Vec3{0.7f, 0.1f, -1.0f});
    const Vec3 n{0, 0, 1};
    const auto inside = refract(d, n, 1.0f / 1.5f);
    ASSERT_TRUE(inside.has_value());
    const auto out = refract(*inside, n, 1.5f);
    ASSERT_TRUE(out.has_value());
    EXPECT_NEAR(out->x, d.x, 1e-6);
    EXPECT_NEAR(out->y, d.y, 1e-6);
    EXPECT_NEAR(out->z, d.z, 1e-6);
}

TEST(Refraction, TotalInternalReflectionBeyondCriticalAngle) {
    const float critical = std::asin(1.0f / 1.5f);
    const Vec3 n{0, 0, 1};
    auto at = [&](float theta) { return Vec3{std::sin(theta), 0, -std::cos(theta)}; };
    EXPECT_FALSE(refract(at(critical + 0.01f), n, 1.5f).has_value());
    EXPECT_TRUE(refract(at(critical - 0.01f), n, 1.5f).has_value());
}

}  // namespace
}  // namespace hikari
