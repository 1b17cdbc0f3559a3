#include "hikari/integrators/whitted/ray_cone.h"

#include <cmath>

#include <gtest/gtest.h>

namespace hikari {
namespace {

TEST(RayCone, CameraSpreadIsOnePixel) {
    Camera camera;
    camera.fov_y_degrees = 90;
    camera.height = 200;
    // tan 45° = 1: the image plane at distance 1 is 2 units high, 0.01 per pixel.
    EXPECT_NEAR(pixel_spread_angle(camera), std::atan(0.01f), 1e-7f);
}

TEST(RayCone, CameraConesAreOnePixelWideAtEveryViewDepth) {
    Camera camera;
    camera.eye = {1, 2, 3};
    camera.look_at = {1, 2, -7};
    camera.height = 100;
    const CameraCones cones(camera);
    // A ray 40° off axis reaching view depth 5 has travelled 5 / cos 40°: its width there is
    // the on-axis ray's at depth 5.
    const float off = 40 * 3.14159265f / 180;
    const RayCone side = cones({std::sin(off), 0, -std::cos(off)});
    const RayCone centre = cones({0, 0, -1});
    EXPECT_EQ(side.width, 0.0f);
    EXPECT_NEAR(side.width_at(5 / std::cos(off)), centre.width_at(5), 1e-7f);
    EXPECT_NEAR(centre.spread, pixel_spread_angle(camera), 1e-9f);
}

TEST(RayCone, FlatMirrorKeepsTheSpread) {
    // Camera ray to a flat mirror 3 units away, then 2 units to the textured surface: the
    // width there is the spread times the whole path, as if the mirror were not there.
    const RayCone camera{0.0f, 0.002f};
    const float at_mirror = camera.width_at(3.0f);
    const RayCone mirrored = reflected_cone(camera, at_mirror, 0.0f);
    EXPECT_NEAR(mirrored.width_at(2.0f), 0.002f * 5.0f, 1e-7f);
}

TEST(RayCone, ConvexMirrorWidensTheCone) {
    // A sphere of radius 0.5 seen from outside turns the normal by width / r across the
    // footprint; the mirror ray by twice that.
    const RayCone camera{0.0f, 0.002f};
    const float width = camera.width_at(3.0f);
    const RayCone mirrored = reflected_cone(camera, width, 1.0f / 0.5f);
    EXPECT_NEAR(mirrored.spread, 0.002f + 2.0f * width / 0.5f, 1e-7f);
    EXPECT_GT(mirrored.width_at(2.0f), camera.width_at(5.0f));
    // Seen from inside (a concave mirror) it narrows instead.
    EXPECT_LT(reflected_cone(camera, width, -2.0f).width_at(2.0f), camera.width_at(5.0f));
}

TEST(RayCone, RefractionHeadOnScalesTheSpreadByEta) {
    const RayCone camera{0.0f, 0.002f};
    const RayCone flat = refracted_cone(camera, 0.01f, 0.0f, 1.0f / 1.5f, 1.0f, 1.0f);
    EXPECT_NEAR(flat.spread, 0.002f / 1.5f, 1e-8f);
    EXPECT_EQ(flat.width, 0.01f);
    // Entering a convex glass surface focuses the cone.
    const RayCone lens = refracted_cone(camera, 0.01f, 2.0f, 1.0f / 1.5f, 1.0f, 1.0f);
    EXPECT_LT(lens.spread, flat.spread);
}

TEST(RayCone, FootprintHeadOnIsTheWidthInTextureUnits) {
    // A plane with one texture repeat per 4 units, met head on by a cone 0.02 wide.
    SurfaceUv uv;
    uv.du_dp = {0.25f, 0, 0};
    uv.dv_dp = {0, 0.25f, 0};
    const UvFootprint f = cone_footprint(0.02f, {0, 0, -1}, {0, 0, 1}, uv);
    EXPECT_NEAR(std::hypot(f.du_dx, f.dv_dx), 0.005f, 1e-7f);
    EXPECT_NEAR(std::hypot(f.du_dy, f.dv_dy), 0.005f, 1e-7f);
    // Negative widths (past a focus) have the same footprint.
    const UvFootprint g = cone_footprint(-0.02f, {0, 0, -1}, {0, 0, 1}, uv);
    EXPECT_NEAR(std::hypot(g.du_dx, g.dv_dx), 0.005f, 1e-7f);
}

TEST(RayCone, FootprintStretchesAlongTheIncidencePlane) {
    // A floor (u along x, v along −z) seen at 60° from the normal, looking down −z: the long
    // axis runs along v and is 1 / cos 60° = 2 times the width; across, along u, 1 times.
    SurfaceUv uv;
    uv.du_dp = {1, 0, 0};
    uv.dv_dp = {0, 0, -1};
    const float s = std::sin(3.14159265f / 3), c = std::cos(3.14159265f / 3);
    const UvFootprint f = cone_footprint(0.1f, {0, -c, -s}, {0, 1, 0}, uv);
    EXPECT_NEAR(f.du_dx, 0.0f, 1e-6f);
    EXPECT_NEAR(std::abs(f.dv_dx), 0.2f, 1e-5f);
    EXPECT_NEAR(std::abs(f.du_dy), 0.1f, 1e-6f);
    EXPECT_NEAR(f.dv_dy, 0.0f, 1e-6f);
}

}  // namespace
}  // namespace hikari
