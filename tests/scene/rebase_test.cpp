#include "hikari/scene/rebase.h"

#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "hikari/io/scene/scene_json.h"
#include "hikari/shading/textures/checker_texture.h"

namespace hikari {
namespace {

Camera camera_at(Vec3 eye, Vec3 look_at) {
    Camera c;
    c.eye = eye;
    c.look_at = look_at;
    return c;
}

TEST(Rebase, ScenesFramedNearTheOriginAreLeftAlone) {
    EXPECT_FALSE(worth_rebasing(camera_at({0, 2, 7}, {0, 1, 0})));             // whitted.json
    EXPECT_FALSE(worth_rebasing(camera_at({278, 273, -800}, {278, 273, 0})));  // a Cornell box
    EXPECT_FALSE(worth_rebasing(camera_at({0, 0, 0}, {0, 0, -1})));
    // Looking one unit ahead from 10 units out: still near.
    EXPECT_FALSE(worth_rebasing(camera_at({0, 1, 10}, {0, 1, 9})));
}

TEST(Rebase, ScenesMovedFarFromWhereTheyAreFramedAreRebased) {
    EXPECT_TRUE(worth_rebasing(camera_at({1e3f, 2, 1e3f + 7}, {1e3f, 1, 1e3f})));
    EXPECT_TRUE(worth_rebasing(camera_at({-1e6f, 2, 7}, {-1e6f, 1, 0})));
    EXPECT_TRUE(worth_rebasing(camera_at({0, 5e4f, 0}, {1, 5e4f, 0})));
}

TEST(Rebase, MovesPositionsAndKeepsDirections) {
    Scene scene;
    scene.camera = camera_at({1e5f, 2, 1e5f + 7}, {1e5f, 1, 1e5f});
    scene.camera.up = {0, 1, 0};
    scene.lights = {PointLight{{1e5f - 5, 8, 1e5f + 6}, {1, 1, 1}},
                    DirectionalLight{{0, -1, 0}, {1, 1, 1}},
                    AreaLight{{1e5f, 4, 1e5f}, {1, 0, 0}, {0, 0, 1}, {2, 2, 2}}};
    scene.spheres = {Sphere{.center = {1e5f + 2, 1, 1e5f - 1}}};
    scene.planes = {Plane{.point = {1e5f, 0, 1e5f}, .normal = {0, 1, 0}}};
    scene.triangles.positions = {{1e5f + 1, 0.5f, 1e5f - 2}};

    const Scene r = rebased_to_camera(scene);
    EXPECT_EQ(r.camera.eye, Vec3(0, 0, 0));
    EXPECT_EQ(r.camera.look_at, Vec3(0, -1, -7));
    EXPECT_EQ(r.camera.up, Vec3(0, 1, 0));
    EXPECT_EQ(std::get<PointLight>(r.lights[0]).position, Vec3(-5, 6, -1));
    EXPECT_EQ(std::get<DirectionalLight>(r.lights[1]).direction, Vec3(0, -1, 0));
    const AreaLight& area = std::get<AreaLight>(r.lights[2]);
    EXPECT_EQ(area.corner, Vec3(0, 2, -7));
    EXPECT_EQ(area.edge1, Vec3(1, 0, 0));
    EXPECT_EQ(r.spheres[0].center, Vec3(2, -1, -8));
    EXPECT_EQ(r.planes[0].point, Vec3(0, -2, -7));
    EXPECT_EQ(r.planes[0].normal, Vec3(0, 1, 0));
    EXPECT_EQ(r.triangles.positions[0], Vec3(1, -1.5f, -9));
    EXPECT_FALSE(worth_rebasing(r.camera));
}

/// The checker's colour index (0: colour_a, 1: colour_b) at `p`.
int checker_cell(const CheckerTexture& t, Vec3 p) {
    SurfacePoint<float> s;
    s.position = p;
    return texture_colour(t, s).x == t.color_b.x ? 1 : 0;
}

TEST(Rebase, SolidCheckerStaysOnTheSurfaces) {
    Scene scene;
    scene.camera = camera_at({12345.25f, 0.5f, -67890.5f}, {12345.25f, 0.5f, -67891.5f});
    CheckerTexture checker{
        .size = 0.75f, .color_a = Vec3(0.0f), .color_b = Vec3(1.0f), .offset = {0.1f, 0.5f, 0.2f}};
    scene.materials.push_back(Material{.texture = checker});
    const Scene r = rebased_to_camera(scene);
    const CheckerTexture& moved = std::get<CheckerTexture>(*r.materials[0].texture);
    EXPECT_LT(std::abs(moved.offset.x), 2.0f);  // as small as the cells, not 10⁴
    // A checker moved along with the scene (offset −eye) comes back to offset 0.
    Scene carried = scene;
    std::get<CheckerTexture>(*carried.materials[0].texture).offset = -scene.camera.eye;
    EXPECT_EQ(std::get<CheckerTexture>(*rebased_to_camera(carried).materials[0].texture).offset,
              Vec3(0.0f));
    const Vec3 eye = scene.camera.eye;
    // Steps of 2⁻⁷, the float spacing at 67890, so that eye + local is exact.
    for (int i = -384; i <= 384; i += 13)
        for (int k = -384; k <= 384; k += 17) {
            const Vec3 local{i / 128.0f, (i + k) / 256.0f, k / 128.0f};
            const Vec3 p = eye + local;
            // Points within rounding of a cell boundary may fall on either side: skip them.
            const auto near_boundary = [&](float x, float offset) {
                const double cells = (double(x) + offset) / checker.size;
                return std::abs(cells - std::round(cells)) < 1e-3;
            };
            if (near_boundary(p.x, 0.1f) || near_boundary(p.y, 0.5f) || near_boundary(p.z, 0.2f))
                continue;
            EXPECT_EQ(checker_cell(checker, p), checker_cell(moved, local))
                << local.x << " " << local.y << " " << local.z;
        }
}

/// An object placed by a translation of 10³ or 10⁶ units is not "singular": the singularity test
/// looks at the transform's linear part only (core/mat4.h, flattens_space).
TEST(Rebase, FarTranslatedObjectsLoad) {
    for (const char* offset : {"1000", "1e6"}) {
        const std::string json = std::string(R"({"objects": [{"type": "triangle",
            "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]],
            "transform": [{"scale": 2}, {"translate": [)") +
                                 offset + R"(, 0, 0]}]}]})";
        std::vector<std::string> warnings;
        const Scene scene = parse_scene(json, "far.json", ".", warnings);
        ASSERT_EQ(scene.triangles.positions.size(), 3u) << offset;
        EXPECT_EQ(scene.triangles.positions[0].x, std::stof(offset)) << offset;
    }
}

}  // namespace
}  // namespace hikari
