#include "hikari/raster/shadow_map.h"

#include <gtest/gtest.h>

#include <string>

#include <fmt/format.h>

#include "hikari/integrators/whitted/whitted.h"
#include "hikari/raster/scanline.h"
#include "hikari/raster/tessellate.h"
#include "hikari/raster/zbuffer.h"
#include "hikari/shading/lights.h"
#include "raster_test_util.h"

namespace hikari {
namespace {

/// A small square caster of half-size `h` centred on `c`, facing along `n` (a coordinate axis),
/// as two triangle objects with `extra` keys.
std::string square_at(Vec3 c, Vec3 n, float h, const std::string& extra = "") {
    const Vec3 a = std::abs(n.y) > 0.5f ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 b = cross(n, a);
    const Vec3 p[4] = {c - a * h - b * h, c + a * h - b * h, c + a * h + b * h, c - a * h + b * h};
    auto v = [](Vec3 q) { return fmt::format("[{}, {}, {}]", q.x, q.y, q.z); };
    return fmt::format(
        R"({{"type": "triangle", "vertices": [{}, {}, {}]{}}}, {{"type": "triangle", "vertices": [{}, {}, {}]{}}})",
        v(p[0]), v(p[1]), v(p[2]), extra, v(p[0]), v(p[2]), v(p[3]), extra);
}

struct Built {
    Scene scene;
    RasterScene raster;
    ShadowMaps maps;
};

/// The scene of `objects` and `light`, its shadow maps built.
Built build(const std::string& light, const std::string& objects, int size = 256) {
    Built b;
    b.scene = testing::raster_scene_from(R"({"camera": {"eye": [0, 0, 10], "look_at": [0, 0, 0]},
        "lights": [)" + light + R"(], "objects": [)" +
                                         objects + "]}");
    b.raster = tessellate_scene(b.scene);
    b.maps =
        build_shadow_maps(b.scene, b.raster, shadow_casting_triangles(b.scene, b.raster), size);
    return b;
}

TEST(ShadowMap, CubeMapShadowsEachAxisOnlyBehindItsOwnCaster) {
    // A point light at the origin with a square caster at distance 1 on each of the six axes:
    // the point at distance 2 behind each caster is in shadow, points between the axes are lit.
    const Vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    std::string objects;
    for (const Vec3& a : axes) objects += (objects.empty() ? "" : ", ") + square_at(a, a, 0.2f);
    const Built b =
        build(R"({"type": "point", "position": [0, 0, 0], "intensity": [1, 1, 1]})", objects);
    ASSERT_TRUE(b.maps.lights[0]);
    const LightShadowMap& map = *b.maps.lights[0];
    EXPECT_EQ(map.faces.size(), 6u);
    for (const Vec3& a : axes) {
        SCOPED_TRACE(fmt::format("axis {} {} {}", a.x, a.y, a.z));
        EXPECT_FALSE(lit_in_shadow_map(map, a * 2.0f, -a));
        // Beside the caster (its shadow is a cone of half-angle ~0.2) and in front of it.
        const Vec3 side = std::abs(a.y) > 0.5f ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
        EXPECT_TRUE(lit_in_shadow_map(map, a * 2.0f + side * 1.0f, -a));
        EXPECT_TRUE(lit_in_shadow_map(map, a * 0.5f, -a));
    }
    EXPECT_TRUE(lit_in_shadow_map(map, Vec3(1.5f, 1.5f, 1.5f), normalize(Vec3(-1.0f))));
}

TEST(ShadowMap, DirectionalMapShadowsBelowTheCasterAndNothingElse) {
    const Built b =
        build(R"({"type": "directional", "direction": [0, -1, 0], "intensity": [1, 1, 1]})",
              square_at({0, 1, 0}, {0, 1, 0}, 0.5f));
    ASSERT_TRUE(b.maps.lights[0]);
    const LightShadowMap& map = *b.maps.lights[0];
    EXPECT_TRUE(map.directional);
    EXPECT_FALSE(lit_in_shadow_map(map, {0, -1, 0}, {0, 1, 0}));
    EXPECT_FALSE(lit_in_shadow_map(map, {0.45f, -1, -0.45f}, {0, 1, 0}));
    EXPECT_TRUE(lit_in_shadow_map(map, {0.6f, -1, 0}, {0, 1, 0}));
    EXPECT_TRUE(lit_in_shadow_map(map, {3, -1, 3}, {0, 1, 0}));
    // Above the caster, toward the light: lit.
    EXPECT_TRUE(lit_in_shadow_map(map, {0, 2, 0}, {0, 1, 0}));
}

TEST(ShadowMap, CubeFacesThatSeeNoCasterAreNotDrawn) {
    // One caster below a point light: only the −y face of its cube map is drawn, and the
    // undrawn faces hold no caster.
    const Built b = build(R"({"type": "point", "position": [0, 0, 0], "intensity": [1, 1, 1]})",
                          square_at({0, -1, 0}, {0, 1, 0}, 0.3f));
    ASSERT_TRUE(b.maps.lights[0]);
    const LightShadowMap& map = *b.maps.lights[0];
    ASSERT_EQ(map.faces.size(), 6u);
    for (size_t f = 0; f < 6; ++f) EXPECT_EQ(map.faces[f].depth.empty(), f != 3) << f;
    EXPECT_FALSE(lit_in_shadow_map(map, {0, -2, 0}, {0, 1, 0}));
    for (const Vec3& p : {Vec3(2, 0, 0), Vec3(0, 2, 0), Vec3(0, 0, -2), Vec3(-2, 0.5f, 0)})
        EXPECT_TRUE(lit_in_shadow_map(map, p, normalize(-p)));
}

TEST(ShadowMap, GrazingLightLeavesALitPlaneWithoutAcne) {
    // A ground of two triangles that is both caster and receiver, lit 85° from its normal: every
    // point on it must come out lit (the slope-scaled bias and the normal offset at work).
    const std::string ground =
        R"({"type": "triangle", "vertices": [[-5, 0, -5], [-5, 0, 5], [5, 0, 5]]},
           {"type": "triangle", "vertices": [[-5, 0, -5], [5, 0, 5], [5, 0, -5]]})";
    const float angle = 85.0f * 3.14159265f / 180.0f;
    for (const std::string light :
         {fmt::format(
              R"({{"type": "directional", "direction": [{}, {}, 0.3], "intensity": [1, 1, 1]}})",
              std::sin(angle), -std::cos(angle)),
          std::string(R"({"type": "point", "position": [-40, 3, 1], "intensity": [1, 1, 1]})")}) {
        SCOPED_TRACE(light);
        const Built b = build(light, ground, 512);
        ASSERT_TRUE(b.maps.lights[0]);
        int shadowed = 0;
        for (int i = 0; i < 100; ++i)
            for (int j = 0; j < 100; ++j) {
                const Vec3 p(-4.9f + 0.098f * i, 0.0f, -4.9f + 0.098f * j);
                if (!lit_in_shadow_map(*b.maps.lights[0], p, {0, 1, 0})) ++shadowed;
            }
        EXPECT_EQ(shadowed, 0);
    }
}

TEST(ShadowMap, ObjectsThatCastNoShadowAreLeftOut) {
    const Built b =
        build(R"({"type": "directional", "direction": [0, -1, 0], "intensity": [1, 1, 1]})",
              square_at({0, 1, 0}, {0, 1, 0}, 0.5f, R"(, "casts_shadow": false)"));
    EXPECT_FALSE(b.maps.lights[0]);
}

TEST(ShadowMap, PlanesBlockExactlyTheOtherSide) {
    const Scene scene = testing::raster_scene_from(R"({
        "lights": [{"type": "point", "position": [0, 2, 0], "intensity": [1, 1, 1]},
                   {"type": "directional", "direction": [0, -1, 0], "intensity": [1, 1, 1]}],
        "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0]}]})");
    for (const Light& light : scene.lights) {
        EXPECT_FALSE(plane_blocks_light(scene, shadow_view(light), {0, 1, 0}));
        EXPECT_TRUE(plane_blocks_light(scene, shadow_view(light), {3, -1, 0}));
        EXPECT_FALSE(
            plane_blocks_light(scene, shadow_view(light), {3, 0, 0}));  // on the plane itself
    }
}

TEST(ShadowMap, RasterShadowsAgreeWithTheRayTracer) {
    // Boxes and a sphere on a ground of triangles under a point and a directional light.
    const std::string objects =
        testing::box({-1.2f, 0, -0.6f}, {-0.2f, 1, 0.4f}) + ", " +
        testing::box({0.4f, 0, -1.4f}, {1.0f, 1.6f, -0.8f}) +
        R"(, {"type": "sphere", "center": [0.9, 0.5, 0.8], "radius": 0.5, "material": "m"},
        {"type": "triangle", "vertices": [[-6, 0, -6], [-6, 0, 6], [6, 0, 6]], "material": "m"},
        {"type": "triangle", "vertices": [[-6, 0, -6], [6, 0, 6], [6, 0, -6]], "material": "m"})";
    const Scene scene = testing::raster_scene_from(
        R"({"camera": {"eye": [1.5, 3.5, 5], "look_at": [0, 0.3, 0], "fov_y": 50, "width": 160, "height": 120},
        "ambient": [0.1, 0.1, 0.1], "materials": {"m": {"ka": [1, 1, 1], "kd": [0.7, 0.7, 0.7]}},
        "lights": [{"type": "point", "position": [2, 4, 2], "intensity": [12, 12, 12]},
                   {"type": "directional", "direction": [-0.5, -1, -0.3], "intensity": [0.6, 0.6, 0.6]}],
        "objects": [)" +
        objects + "]}");
    const Framebuffer ray = render_whitted(scene, Film(scene.camera));
    RasterSettings raster;
    raster.shadows = ShadowMode::map;
    raster.shadow_map_size = 1024;
    const Framebuffer z = render_zbuffer(scene, Film(scene.camera), {}, raster);
    const Framebuffer s = render_scanline(scene, Film(scene.camera), {}, raster);
    EXPECT_GE(testing::psnr(z, ray), 30.0);
    EXPECT_GE(testing::psnr(s, ray), 30.0);
    // Without shadows the pictures differ clearly: the shadows are really drawn.
    raster.shadows = ShadowMode::none;
    EXPECT_LT(testing::psnr(render_zbuffer(scene, Film(scene.camera), {}, raster), ray), 25.0);
}

}  // namespace
}  // namespace hikari
