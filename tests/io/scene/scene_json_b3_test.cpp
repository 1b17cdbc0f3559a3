// The scene-format additions for the Whitted benchmark scene (B3): checker texture, gradient
// sky, casts_shadow and point-light falloff.
#include <gtest/gtest.h>

#include "../scene_test_util.h"
#include "hikari/core/error.h"
#include "hikari/io/scene/scene_json.h"
#include "hikari/shading/lights.h"
#include "hikari/shading/textures/checker_texture.h"

namespace hikari {
namespace {

using testing::error_of;
using testing::parse;

TEST(SceneJsonB3, CheckerTextureParsesAndAlternates) {
    const Scene s = parse(R"({"materials": {"floor": {"ka": 0.1, "kd": 0.8, "texture":
        {"type": "checker", "size": 2, "color_a": [1, 0, 0], "color_b": 0.5, "offset": [0, 0.5, 0]}}},
        "objects": []})");
    ASSERT_TRUE(s.materials[0].texture.has_value());
    const auto& t = std::get<CheckerTexture>(*s.materials[0].texture);
    EXPECT_EQ(t.size, 2.0f);
    const auto at = [&](Vec3 p) {
        SurfacePoint<float> point;
        point.position = p;
        return texture_colour(t, point);
    };
    EXPECT_EQ(at({0.5f, 0, 0.5f}), Vec3(1, 0, 0));
    EXPECT_EQ(at({2.5f, 0, 0.5f}), Vec3(0.5f));
    EXPECT_EQ(at({-0.5f, 0, 0.5f}), Vec3(0.5f));
    EXPECT_EQ(at({-0.5f, 0, -0.5f}), Vec3(1, 0, 0));
    EXPECT_EQ(at({0.5f, -1e-7f, 0.5f}), Vec3(1, 0, 0));  // the offset keeps y = 0 in one cell
}

TEST(SceneJsonB3, GradientSkyBlendsByDirection) {
    const Scene s =
        parse(R"({"sky": {"type": "gradient", "horizon": [1, 1, 1], "zenith": [0, 0, 1]},
        "objects": []})");
    EXPECT_TRUE(s.sky.gradient);
    EXPECT_EQ(s.sky.colour({0, 1, 0}, Vec3(0)), Vec3(0, 0, 1));
    EXPECT_EQ(s.sky.colour({1, 0, 0}, Vec3(0)), Vec3(1, 1, 1));
    EXPECT_EQ(s.sky.colour({0, -1, 0}, Vec3(0)), Vec3(1, 1, 1));
    EXPECT_EQ(s.sky.colour({0, 0.5f, 0}, Vec3(0)), Vec3(0.5f, 0.5f, 1));
    EXPECT_EQ(parse(R"({"background": 0.3, "objects": []})").sky.colour({0, 1, 0}, Vec3(0.3f)),
              Vec3(0.3f));
}

TEST(SceneJsonB3, CastsShadowAndFalloff) {
    const Scene s = parse(R"({"lights": [
        {"type": "point", "position": [0, 1, 0], "intensity": 1, "falloff": "none"},
        {"type": "point", "position": [0, 1, 0], "intensity": 1}],
        "objects": [
        {"type": "sphere", "center": [0, 0, 0], "radius": 1, "casts_shadow": false},
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0]},
        {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "casts_shadow": false}]})");
    EXPECT_FALSE(std::get<PointLight>(s.lights[0]).inverse_square);
    EXPECT_TRUE(std::get<PointLight>(s.lights[1]).inverse_square);
    EXPECT_FALSE(s.spheres[0].casts_shadow);
    EXPECT_TRUE(s.planes[0].casts_shadow);
    ASSERT_EQ(s.triangles.casts_shadow.size(), 1u);
    EXPECT_EQ(s.triangles.casts_shadow[0], 0);
    EXPECT_EQ(sample_light<float>(s.lights[0], Vec3(0, 5, 0)).irradiance, Vec3(1));
}

TEST(SceneJsonB3, BadAdditionsNameTheirJsonPath) {
    EXPECT_EQ(error_of(R"({"sky": {"type": "stars"}, "objects": []})"),
              "s.json: sky.type: unknown sky type \"stars\" (expected \"gradient\")");
    EXPECT_EQ(error_of(R"({"sky": {"type": "gradient", "horizon": 1}, "objects": []})"),
              "s.json: sky.zenith: missing (this key is required)");
    EXPECT_EQ(error_of(R"({"materials": {"m": {"texture": {"type": "checker", "size": 0}}},
        "objects": []})"),
              "s.json: materials.m.texture.size: expected a positive number");
    EXPECT_EQ(error_of(R"({"materials": {"m": {"texture": {"type": "marble"}}}, "objects": []})"),
              "s.json: materials.m.texture.type: unknown texture type \"marble\" (expected "
              "\"checker\" or \"image\")");
    EXPECT_EQ(error_of(R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
        "casts_shadow": "no"}]})"),
              "s.json: objects[0].casts_shadow: expected true or false");
    EXPECT_EQ(error_of(R"({"lights": [{"type": "point", "position": [0, 0, 0], "intensity": 1,
        "falloff": "linear"}], "objects": []})"),
              "s.json: lights[0].falloff: unknown falloff \"linear\" (expected "
              "\"inverse_square\" or \"none\")");
}

TEST(SceneJsonB3, BenchSceneLoads) {
    std::vector<std::string> warnings;
    const Scene s = load_scene_file(HIKARI_SOURCE_DIR "/scenes/bench/whitted.json", warnings);
    EXPECT_EQ(s.spheres.size(), 3u);
    EXPECT_EQ(s.planes.size(), 1u);
    EXPECT_EQ(s.camera.width, 1920);
    EXPECT_TRUE(warnings.empty());
}

}  // namespace
}  // namespace hikari
