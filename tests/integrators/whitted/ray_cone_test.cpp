#include "hikari/integrators/whitted/ray_cone.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hikari/integrators/whitted/whitted.h"
#include "hikari/io/scene/scene_json.h"

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

TEST(RayCone, TriangleCurvatureFromVertexNormals) {
    // Three points of a sphere of radius 2 with its outward normals: curvature 1/2.
    const Vec3 c{1, -1, 0.5f};
    const std::array<Vec3, 3> n{normalize(Vec3(0.2f, 1, 0.1f)), normalize(Vec3(0.5f, 0.9f, 0)),
                                normalize(Vec3(0.1f, 0.8f, 0.4f))};
    const std::array<Vec3, 3> p{c + 2.0f * n[0], c + 2.0f * n[1], c + 2.0f * n[2]};
    EXPECT_NEAR(triangle_curvature(p, n), 0.5f, 1e-5f);
    // Normals pointing in (a concave side): −1/2; flat normals: 0.
    EXPECT_NEAR(triangle_curvature(p, {-n[0], -n[1], -n[2]}), -0.5f, 1e-5f);
    EXPECT_EQ(triangle_curvature(p, {n[0], n[0], n[0]}), 0.0f);
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

/// A textured wall (a 20 × 20 quad at z = `wall_z`, the checker image repeated 20 times across
/// it) and the objects of JSON text `more` (", {...}" or ""), seen from `eye` looking at
/// `look_at`: 64 × 64 pixels, 30° field of view, ambient light only.
Scene wall_scene(Vec3 eye, Vec3 look_at, float wall_z, const char* more) {
    const std::string json = R"({"camera": {"eye": [)" + std::to_string(eye.x) + "," +
                             std::to_string(eye.y) + "," + std::to_string(eye.z) +
                             R"(], "look_at": [)" + std::to_string(look_at.x) + "," +
                             std::to_string(look_at.y) + "," + std::to_string(look_at.z) +
                             R"(], "fov_y": 30, "width": 64, "height": 64},
      "ambient": 1,
      "materials": {"wall": {"ka": 1, "texture": {"type": "image",
                                                  "file": "scenes/models/checker.png"}},
                    "mirror": {"reflectivity": 1}},
      "objects": [
        {"type": "triangle", "vertices": [[-10, -10, W], [10, -10, W], [10, 10, W]],
         "uvs": [[0, 0], [20, 0], [20, 20]], "material": "wall"},
        {"type": "triangle", "vertices": [[-10, -10, W], [10, 10, W], [-10, 10, W]],
         "uvs": [[0, 0], [20, 20], [0, 20]], "material": "wall"})" +
                             std::string(more) + "]}";
    std::string text = json;
    for (size_t at = text.find(", W]"); at != std::string::npos; at = text.find(", W]"))
        text.replace(at, 4, ", " + std::to_string(wall_z) + "]");
    std::vector<std::string> warnings;
    return parse_scene(text, "wall.json", HIKARI_SOURCE_DIR, warnings);
}

TEST(RayCone, MirroredTextureMatchesTheDirectViewAtTheSameDistance) {
    // Through a flat mirror 5 units ahead, the eye sees a wall 5 units behind it: 15 units of
    // path, so the texture's level of detail must be that of the wall seen directly from 15
    // units (the image mirrored left to right). The squares are about a pixel there, so the
    // level matters: a cone restarted at the mirror would pick one a half level finer.
    const Scene mirrored = wall_scene({0, 0, 0}, {0, 0, -1}, 5.0f,
                                      R"(, {"type": "plane", "point": [0, 0, -5],
                                      "normal": [0, 0, 1], "material": "mirror"})");
    const Scene direct = wall_scene({0, 0, -10}, {0, 0, 0}, 5.0f, "");
    const Framebuffer a = render_whitted(mirrored, Film(mirrored.camera));
    const Framebuffer b = render_whitted(direct, Film(direct.camera));
    double worst = 0, spread = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const Vec3 p = a.film.linear().at(x, y), q = b.film.linear().at(63 - x, y);
            worst = std::max(worst, static_cast<double>(std::abs(p.x - q.x)));
            spread =
                std::max(spread, static_cast<double>(std::abs(p.x - a.film.linear().at(0, 0).x)));
        }
    EXPECT_LT(worst, 0.01);
    EXPECT_GT(spread, 0.1);  // the texture is still visible: the comparison means something
}

}  // namespace
}  // namespace hikari
