#include "hikari/core/mat4.h"

#include <gtest/gtest.h>

#include "../support/expect_near.h"

namespace hikari {
namespace {

using testing::expect_near;

TEST(Mat4, IdentityLeavesPointsAlone) {
    expect_near(transform_point(Mat4::identity(), {1, 2, 3}), {1, 2, 3}, 1e-5f);
}

TEST(Mat4, TranslateMovesPointsNotDirections) {
    const Mat4 t = translate({1, 2, 3});
    expect_near(transform_point(t, {1, 1, 1}), {2, 3, 4}, 1e-5f);
    expect_near(transform_direction(t, {1, 1, 1}), {1, 1, 1}, 1e-5f);
}

TEST(Mat4, ScaleScalesPerAxis) {
    expect_near(transform_point(scale({2, 3, 4}), {1, 1, 1}), {2, 3, 4}, 1e-5f);
}

TEST(Mat4, RotateAboutZIsCounterClockwise) {
    expect_near(transform_point(rotate({0, 0, 1}, 90), {1, 0, 0}), {0, 1, 0}, 1e-5f);
    expect_near(transform_point(rotate({0, 0, 2}, 180), {1, 0, 0}), {-1, 0, 0}, 1e-5f);
    expect_near(transform_point(rotate({1, 0, 0}, 90), {0, 1, 0}), {0, 0, 1}, 1e-5f);
}

TEST(Mat4, ProductAppliesRightFactorFirst) {
    const Mat4 m = translate({1, 0, 0}) * scale({2, 2, 2});
    expect_near(transform_point(m, {1, 1, 1}), {3, 2, 2}, 1e-5f);
}

TEST(Mat4, InverseUndoesTransform) {
    const Mat4 m = translate({1, -2, 3}) * rotate({1, 1, 0}, 33) * scale({2, 0.5f, 3});
    Mat4 inv;
    ASSERT_TRUE(invert(m, inv));
    const Mat4 p = m * inv;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_NEAR(p(i, j), i == j ? 1.0f : 0.0f, 1e-5f);
}

TEST(Mat4, SingularMatrixDoesNotInvert) {
    Mat4 inv = Mat4::identity();
    EXPECT_FALSE(invert(scale({1, 0, 1}), inv));
    EXPECT_EQ(inv, Mat4::identity());
}

TEST(Mat4, FarTranslationsInvertAndDoNotFlatten) {
    // A model placed far from the origin (CAD, georeferenced): the translation does not make
    // the transform singular.
    const Mat4 m = translate({1e4f, 0, -3e3f}) * rotate({0, 1, 0}, 20) * scale(Vec3(2.0f));
    Mat4 inv;
    ASSERT_TRUE(invert(m, inv));
    expect_near(transform_point(inv, transform_point(m, {1, 2, 3})), {1, 2, 3}, 1e-3f);
    EXPECT_TRUE(invert(translate({1e6f, 0, -3e5f}) * scale(Vec3(0.001f)), inv));
    EXPECT_FALSE(flattens_space(m));
    EXPECT_FALSE(flattens_space(translate({1000, 0, 0})));
    EXPECT_TRUE(flattens_space(scale({1, 0, 1})));
    EXPECT_TRUE(flattens_space(scale({1, 1e-10f, 1})));
}

TEST(Mat4, DeterminantOfScaleIsProduct) {
    EXPECT_NEAR(determinant(scale({2, 3, 4})), 24.0f, 1e-5f);
}

TEST(Mat4, NormalsStayPerpendicularUnderNonUniformScale) {
    const Mat4 m = scale({4, 1, 1});
    Mat4 inv;
    ASSERT_TRUE(invert(m, inv));
    const Vec3 tangent = transform_direction(m, {1, -1, 0});
    const Vec3 normal = transform_normal(transpose(inv), {1, 1, 0});
    EXPECT_NEAR(dot(tangent, normal), 0.0f, 1e-6f);
}

TEST(Mat4, LookAtPutsTargetOnNegativeZ) {
    const Mat4 v = look_at({1, 2, 3}, {1, 2, -7}, {0, 1, 0});
    expect_near(transform_point(v, {1, 2, -7}), {0, 0, -10}, 1e-5f);
    expect_near(transform_point(v, {1, 3, 3}), {0, 1, 0}, 1e-5f);
}

TEST(Mat4, PerspectiveMapsNearAndFarToNdcRange) {
    const Mat4 p = perspective(90, 1, 1, 10);
    EXPECT_NEAR(transform_point(p, {0, 0, -1}).z, -1.0f, 1e-6f);
    EXPECT_NEAR(transform_point(p, {0, 0, -10}).z, 1.0f, 1e-5f);
    // fov 90: a point at 45 degrees lands on the edge of the image.
    EXPECT_NEAR(transform_point(p, {0, 2, -2}).y, 1.0f, 1e-6f);
}

TEST(Mat4, ViewportPutsNdcCornersOnPixelEdges) {
    const Mat4 v = viewport(640, 480);
    expect_near(transform_point(v, {-1, 1, -1}), {0, 0, 0}, 1e-5f);
    expect_near(transform_point(v, {1, -1, 1}), {640, 480, 1}, 1e-5f);
}

}  // namespace
}  // namespace hikari
