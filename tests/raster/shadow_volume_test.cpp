#include "hikari/raster/shadow_volume.h"

#include <gtest/gtest.h>

#include <string>

#include <fmt/format.h>

#include "hikari/integrators/whitted/whitted.h"
#include "hikari/raster/depth_sort.h"
#include "hikari/raster/zbuffer.h"
#include "raster_test_util.h"

namespace hikari {
namespace {

/// A closed unit cube centred at `c`, 12 triangles wound outward.
TriangleSet cube(Vec3 c) {
    TriangleSet t;
    for (int i = 0; i < 8; ++i)
        t.positions.push_back(
            c + Vec3((i & 1) ? 0.5f : -0.5f, (i & 2) ? 0.5f : -0.5f, (i & 4) ? 0.5f : -0.5f));
    t.normals.assign(8, Vec3(0, 1, 0));
    const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                  {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        t.indices.push_back({q[0], q[1], q[2]});
        t.indices.push_back({q[0], q[2], q[3]});
    }
    t.material.assign(12, 0);
    t.id.assign(12, 0);
    return t;
}

int sides_of(const std::vector<VolumePolygon>& polygons) {
    int sides = 0;
    for (const VolumePolygon& p : polygons)
        if (p.v[0].w == 1.0f && p.v[1].w == 1.0f && p.v[2].w == 0.0f) ++sides;
    return sides;
}

TEST(ShadowVolume, ClosedCubeIsExtrudedAtItsSilhouetteOnly) {
    const TriangleSet box = cube({0, 0, 0});
    const std::vector<uint8_t> all(box.size(), 1);
    // From straight above only the top faces the light: its four edges are the silhouette.
    const auto above = shadow_volume_polygons(box, all, PointLight{{0, 5, 0}, Vec3(1.0f)});
    EXPECT_EQ(sides_of(above), 4);
    EXPECT_EQ(above.size(), 2u + 2u + 4u);  // front cap, back cap, sides
    // From a corner direction three faces face the light: a hexagonal silhouette.
    const auto corner = shadow_volume_polygons(box, all, PointLight{{5, 5, 5}, Vec3(1.0f)});
    EXPECT_EQ(sides_of(corner), 6);
    EXPECT_EQ(corner.size(), 6u + 6u + 6u);
    // A directional light's back cap is a single point at infinity: none is emitted.
    const auto sun =
        shadow_volume_polygons(box, all, DirectionalLight{normalize(Vec3(-1, -1, -1)), Vec3(1.0f)});
    EXPECT_EQ(sides_of(sun), 6);
    EXPECT_EQ(sun.size(), 6u + 6u);
}

TEST(ShadowVolume, SidesReachInfinityAwayFromTheLight) {
    const TriangleSet box = cube({0, 0, 0});
    const Vec3 light(0.2f, 5, 0.1f);
    for (const VolumePolygon& p :
         shadow_volume_polygons(box, std::vector<uint8_t>(12, 1), PointLight{light, Vec3(1.0f)})) {
        if (p.count != 4) continue;
        // b → a → a∞ → b∞: the points at infinity are the directions from the light.
        const Vec3 a = p.v[1].xyz(), b = p.v[0].xyz();
        EXPECT_EQ(p.v[2].w, 0.0f);
        EXPECT_EQ(p.v[3].w, 0.0f);
        EXPECT_NEAR(length(cross(p.v[2].xyz(), a - light)), 0.0f, 1e-5f);
        EXPECT_NEAR(length(cross(p.v[3].xyz(), b - light)), 0.0f, 1e-5f);
        EXPECT_GT(dot(p.v[2].xyz(), a - light), 0.0f);
    }
}

TEST(ShadowVolume, OpenMeshesKeepTheirBorders) {
    // One triangle: its own volume, all three sides, front and back cap.
    TriangleSet one;
    one.positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, -1}};
    one.normals.assign(3, Vec3(0, 1, 0));
    one.indices = {{0, 1, 2}};
    one.material = {0};
    one.id = {0};
    const auto volume = shadow_volume_polygons(one, {1}, PointLight{{0, 3, 0}, Vec3(1.0f)});
    EXPECT_EQ(sides_of(volume), 3);
    EXPECT_EQ(volume.size(), 5u);
    // Facing away, it is turned toward the light first: the same volume.
    const auto below = shadow_volume_polygons(one, {1}, PointLight{{0, -3, 0}, Vec3(1.0f)});
    EXPECT_EQ(below.size(), 5u);
}

const char* const k_ground =
    R"({"type": "triangle", "vertices": [[-8, 0, -8], [-8, 0, 8], [8, 0, 8]], "material": "m"},
       {"type": "triangle", "vertices": [[-8, 0, -8], [8, 0, 8], [8, 0, -8]], "material": "m"})";

Scene scene_of(const std::string& camera, const std::string& lights, const std::string& objects) {
    return testing::raster_scene_from(
        R"({"camera": )" + camera +
        R"(, "ambient": [0.1, 0.1, 0.1], "materials": {"m": {"ka": [1, 1, 1], "kd": [0.7, 0.7, 0.7]}},
        "lights": [)" +
        lights + R"(], "objects": [)" + objects + "]}");
}

TEST(ShadowVolume, EyeInsideTheShadowStillCountsRight) {
    // The camera stands under a floating slab, inside its shadow volume, looking at the ground:
    // z-fail counts only what lies behind the visible point, so the volume's missing front
    // does not matter.
    const Scene scene = scene_of(
        R"({"eye": [0, 0.6, 0.3], "look_at": [0.4, 0, -2], "fov_y": 70, "width": 120, "height": 90})",
        R"({"type": "point", "position": [0.2, 6, 0.5], "intensity": [30, 30, 30]})",
        testing::box({-1.5f, 1, -1.5f}, {1.5f, 1.2f, 1.5f}) + ", " +
            testing::box({0.5f, 0, -2}, {0.9f, 0.4f, -1.6f}) + ", " + k_ground);
    const Framebuffer ray = render_whitted(scene, Film(scene.camera));
    RasterSettings raster;
    raster.shadows = ShadowMode::volume;
    EXPECT_GE(testing::psnr(render_zbuffer(scene, Film(scene.camera), {}, raster), ray), 40.0);
}

TEST(ShadowVolume, RasterVolumesAgreeWithTheRayTracer) {
    const Scene scene = scene_of(
        R"({"eye": [1.5, 3.5, 5], "look_at": [0, 0.3, 0], "fov_y": 50, "width": 160, "height": 120})",
        R"({"type": "point", "position": [2, 4, 2], "intensity": [12, 12, 12]},
           {"type": "directional", "direction": [-0.5, -1, -0.3], "intensity": [0.6, 0.6, 0.6]})",
        testing::box({-1.2f, 0, -0.6f}, {-0.2f, 1, 0.4f}) + ", " +
            testing::box({0.4f, 0, -1.4f}, {1.0f, 1.6f, -0.8f}) +
            R"(, {"type": "sphere", "center": [0.9, 0.5, 0.8], "radius": 0.5, "material": "m"}, )" +
            k_ground);
    const Framebuffer ray = render_whitted(scene, Film(scene.camera));
    RasterSettings raster;
    raster.shadows = ShadowMode::volume;
    EXPECT_GE(testing::psnr(render_zbuffer(scene, Film(scene.camera), {}, raster), ray), 40.0);
    EXPECT_GE(testing::psnr(render_depth_sort(scene, Film(scene.camera), {}, raster), ray), 40.0);
}

TEST(ShadowVolume, ObjectsThatCastNoShadowAreLeftOut) {
    std::string boxes = testing::box({-0.5f, 0.5f, -0.5f}, {0.5f, 1.5f, 0.5f});
    // Every triangle of the box: "casts_shadow": false.
    for (size_t at = 0; (at = boxes.find(R"("material": "m"})", at)) != std::string::npos; at += 10)
        boxes.replace(at, 16, R"("material": "m", "casts_shadow": false})");
    const Scene scene =
        scene_of(R"({"eye": [0, 3, 4], "look_at": [0, 0.5, 0], "width": 64, "height": 48})",
                 R"({"type": "point", "position": [0.3, 5, 0.2], "intensity": [20, 20, 20]})",
                 boxes + ", " + k_ground);
    RasterSettings raster;
    raster.shadows = ShadowMode::volume;
    const Framebuffer volume = render_zbuffer(scene, Film(scene.camera), {}, raster);
    raster.shadows = ShadowMode::none;
    const Framebuffer none = render_zbuffer(scene, Film(scene.camera), {}, raster);
    EXPECT_EQ(volume.film.linear().pixels, none.film.linear().pixels);
}

}  // namespace
}  // namespace hikari
