#include "hikari/scene/camera_orbit.h"

#include <cmath>

#include <gtest/gtest.h>

namespace {

using namespace hikari;

Camera tilted_camera() {
    Camera c;
    c.eye = {3.0f, 2.0f, 4.0f};
    c.look_at = {0.5f, -1.0f, 0.25f};
    c.up = {0.0f, 1.0f, 0.0f};
    c.fov_y_degrees = 40.0f;
    c.width = 64;
    c.height = 48;
    return c;
}

TEST(CameraOrbit, FrameZeroIsTheCameraItself) {
    const Camera c = tilted_camera();
    const Camera t = turntable_camera(c, 0, 12);
    EXPECT_EQ(t.eye.x, c.eye.x);
    EXPECT_EQ(t.eye.y, c.eye.y);
    EXPECT_EQ(t.eye.z, c.eye.z);
}

TEST(CameraOrbit, KeepsElevationRadiusAndEverythingButTheEye) {
    const Camera c = tilted_camera();
    const Vec3 offset = c.eye - c.look_at;
    for (int k = 1; k < 12; ++k) {
        const Camera t = turntable_camera(c, k, 12);
        const Vec3 turned = t.eye - t.look_at;
        EXPECT_NEAR(turned.y, offset.y, 1e-5f) << k;  // height above look_at along up
        EXPECT_NEAR(length(turned), length(offset), 1e-5f) << k;
        EXPECT_EQ(t.look_at.x, c.look_at.x);
        EXPECT_EQ(t.fov_y_degrees, c.fov_y_degrees);
        EXPECT_EQ(t.width, c.width);
        EXPECT_EQ(t.height, c.height);
    }
}

TEST(CameraOrbit, QuarterTurnIsCounterClockwiseSeenFromAbove) {
    Camera c;
    c.eye = {0.0f, 1.0f, 5.0f};  // +z of look_at
    c.look_at = {0.0f, 0.0f, 0.0f};
    const Camera t = orbited_camera(c, 0.25);
    // Turning +z by 90 degrees about +y (right-handed) gives +x.
    EXPECT_NEAR(t.eye.x, 5.0f, 1e-5f);
    EXPECT_NEAR(t.eye.y, 1.0f, 1e-6f);
    EXPECT_NEAR(t.eye.z, 0.0f, 1e-5f);
}

TEST(CameraOrbit, TurnsAboutATiltedUpAxis) {
    Camera c;
    c.eye = {1.0f, 0.0f, 0.0f};
    c.look_at = {0.0f, 0.0f, 0.0f};
    c.up = {1.0f, 1.0f, 0.0f};  // not normalized, not perpendicular to the view
    const Vec3 axis = normalize(c.up);
    for (int k = 1; k < 8; ++k) {
        const Camera t = turntable_camera(c, k, 8);
        EXPECT_NEAR(dot(t.eye, axis), dot(c.eye, axis), 1e-6f) << k;
        EXPECT_NEAR(length(t.eye), 1.0f, 1e-6f) << k;
    }
    const Camera half = turntable_camera(c, 4, 8);
    EXPECT_NEAR(half.eye.x, 0.0f, 1e-6f);  // the far side of the cone about the axis
    EXPECT_NEAR(half.eye.y, 1.0f, 1e-6f);
}

}  // namespace
