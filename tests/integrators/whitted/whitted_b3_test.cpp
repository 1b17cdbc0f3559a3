// Whitted ray tracing of the B3 scene-format additions: sky, checker, casts_shadow, falloff.
#include <gtest/gtest.h>

#include "../../io/scene_test_util.h"
#include "hikari/integrators/whitted/whitted.h"
#include "hikari/io/scene/scene_json.h"

namespace hikari {
namespace {

using testing::parse;

/// A camera looking straight down at the floor point (0, 0, 0) from (0, 1, 0), 1 pixel.
constexpr const char* k_camera = R"("camera": {"eye": [0, 1, 0], "look_at": [0, 0, 0],
    "up": [0, 0, -1], "fov_y": 1, "width": 1, "height": 1})";

TEST(WhittedB3, NonCastingSphereLetsLightThrough) {
    const auto render_with = [](const char* casts) {
        const Scene scene = parse(std::string("{") + k_camera + R"(,
          "ambient": 0.25,
          "materials": {"white": {"ka": 1, "kd": 1}},
          "lights": [{"type": "directional", "direction": [0, -1, 0], "intensity": 1}],
          "objects": [
            {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "white"},
            {"type": "sphere", "center": [0, 5, 0], "radius": 0.1, "material": "white",
             "casts_shadow": )" + casts +
                                  "}]}");
        return render_whitted(scene, Film(scene.camera)).film.linear().at(0, 0).x;
    };
    EXPECT_NEAR(render_with("true"), 0.25f, 1e-6);
    EXPECT_NEAR(render_with("false"), 1.25f, 1e-6);
}

TEST(WhittedB3, PointLightWithoutFalloff) {
    const Scene scene = parse(std::string("{") + k_camera + R"(,
      "materials": {"white": {"kd": 0.5}},
      "lights": [{"type": "point", "position": [0, 10, 0], "intensity": 1, "falloff": "none"}],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "white"}]})");
    EXPECT_NEAR(render_whitted(scene, Film(scene.camera)).film.linear().at(0, 0).y, 0.5f, 1e-6);
}

TEST(WhittedB3, CheckerScalesAmbientAndDiffuse) {
    const Scene scene = parse(std::string("{") + k_camera + R"(,
      "ambient": 1,
      "materials": {"floor": {"ka": 0.5, "kd": 0.25, "texture": {"type": "checker",
          "color_a": [1, 0, 0], "color_b": [0, 1, 0], "offset": [0.25, 0.5, 0.25]}}},
      "lights": [{"type": "directional", "direction": [0, -1, 0], "intensity": 1}],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"}]})");
    const Vec3 c = render_whitted(scene, Film(scene.camera)).film.linear().at(0, 0);
    EXPECT_NEAR(c.x, 0.75f, 1e-6);
    EXPECT_EQ(c.y, 0.0f);
}

TEST(WhittedB3, MissesSeeTheGradientSky) {
    const Scene scene = parse(R"({"camera": {"eye": [0, 0, 0], "look_at": [0, 1, 0],
        "up": [0, 0, -1], "fov_y": 1, "width": 1, "height": 1},
        "sky": {"type": "gradient", "horizon": [1, 0, 0], "zenith": [0, 0, 1]}, "objects": []})");
    const Vec3 c = render_whitted(scene, Film(scene.camera)).film.linear().at(0, 0);
    EXPECT_NEAR(c.z, 1.0f, 1e-4);
    EXPECT_NEAR(c.x, 0.0f, 1e-4);
}

}  // namespace
}  // namespace hikari
