#include "hikari/scene/animation.h"

#include <cmath>

#include <gtest/gtest.h>

namespace {

using namespace hikari;

Track<Vec3d> bouncing_keys() {
    return {{0, {0, 0, 0}}, {10, {4, 2, 0}}, {15, {6, 0, 1}}, {30, {0, 3, -2}}};
}

TEST(Animation, KeysAreHitExactlyAndEndsAreHeld) {
    const Track<Vec3d> keys = bouncing_keys();
    for (const KeyInterpolation how : {KeyInterpolation::linear, KeyInterpolation::smooth}) {
        for (const Key<Vec3d>& k : keys) EXPECT_EQ(sample(keys, k.frame, how), k.value);
        EXPECT_EQ(sample(keys, -5, how), keys.front().value);
        EXPECT_EQ(sample(keys, 99, how), keys.back().value);
    }
}

TEST(Animation, LinearIsTheStraightLineBetweenNeighbouringKeys) {
    const Track<Vec3d> keys = bouncing_keys();
    const Vec3d p = sample(keys, 12, KeyInterpolation::linear);  // 2/5 of the way from 10 to 15
    EXPECT_DOUBLE_EQ(p.x, 4 + 0.4 * 2);
    EXPECT_DOUBLE_EQ(p.y, 2 - 0.4 * 2);
    EXPECT_DOUBLE_EQ(p.z, 0.4);
}

TEST(Animation, SmoothHasNoCornerAtAKey) {
    // Catmull-Rom is C1: the slope just before an inner key equals the slope just after it,
    // where the straight lines turn a corner.
    const Track<Vec3d> keys = bouncing_keys();
    const double h = 1e-5;
    for (const double key : {10.0, 15.0}) {
        const auto slope = [&](double a, double b, KeyInterpolation how) {
            return (sample(keys, b, how) - sample(keys, a, how)) / (b - a);
        };
        const Vec3d before = slope(key - h, key, KeyInterpolation::smooth);
        const Vec3d after = slope(key, key + h, KeyInterpolation::smooth);
        EXPECT_NEAR(before.x, after.x, 1e-3);
        EXPECT_NEAR(before.y, after.y, 1e-3);
        const Vec3d line_before = slope(key - h, key, KeyInterpolation::linear);
        const Vec3d line_after = slope(key, key + h, KeyInterpolation::linear);
        EXPECT_GT(std::abs(line_before.y - line_after.y), 0.1);
    }
}

TEST(Animation, SmoothThroughTwoKeysIsTheStraightLine) {
    const Track<Vec3d> keys{{0, {1, 2, 3}}, {8, {5, -2, 3}}};
    for (double f = 0; f <= 8; f += 0.5) {
        const Vec3d s = sample(keys, f, KeyInterpolation::smooth);
        const Vec3d l = sample(keys, f, KeyInterpolation::linear);
        EXPECT_NEAR(s.x, l.x, 1e-12);
        EXPECT_NEAR(s.y, l.y, 1e-12);
    }
}

TEST(Animation, SlerpTurnsAtConstantSpeedAboutTheKeysAxis) {
    const Track<Rotation> keys{{0, rotation_about({0, 2, 0}, 0)},
                               {10, rotation_about({0, 1, 0}, 90)}};
    for (int f = 0; f <= 10; ++f) {
        const AxisAngle a = axis_angle(sample(keys, f));
        EXPECT_NEAR(a.degrees, 9.0 * f, 1e-9);
        if (f > 0) EXPECT_NEAR(a.axis.y, 1.0, 1e-12);
    }
}

TEST(Animation, SlerpTakesTheShorterArc) {
    // 0° to 270° about +z is 90° the other way round: halfway is −45°, that is 45° about −z.
    const Track<Rotation> keys{{0, rotation_about({0, 0, 1}, 0)},
                               {2, rotation_about({0, 0, 1}, 270)}};
    const AxisAngle a = axis_angle(sample(keys, 1));
    EXPECT_NEAR(a.degrees, 45, 1e-9);
    EXPECT_NEAR(a.axis.z, -1, 1e-12);
}

TEST(Animation, AxisAngleUndoesRotationAbout) {
    const AxisAngle a = axis_angle(rotation_about({1, 2, -2}, 130));
    EXPECT_NEAR(a.degrees, 130, 1e-9);
    EXPECT_NEAR(a.axis.x, 1.0 / 3, 1e-12);
    EXPECT_NEAR(a.axis.z, -2.0 / 3, 1e-12);
    EXPECT_EQ(axis_angle(rotation_about({1, 0, 0}, 0)).degrees, 0);
}

TEST(Animation, NumbersAreAlwaysLinear) {
    const Track<double> fov{{0, 30}, {4, 50}, {5, 20}};
    EXPECT_DOUBLE_EQ(sample(fov, 1), 35);
    EXPECT_DOUBLE_EQ(sample(fov, 4.5), 35);
}

TEST(Animation, TransformSamplesOnlyWhatIsKeyed) {
    TransformKeys keys;
    keys.translate = {{0, {0, 0, 0}}, {4, {4, 0, 0}}};
    const TransformAtFrame t = sample(keys, 1, KeyInterpolation::linear);
    EXPECT_FALSE(t.scale);
    EXPECT_FALSE(t.rotate);
    ASSERT_TRUE(t.translate);
    EXPECT_DOUBLE_EQ(t.translate->x, 1);
}

}  // namespace
