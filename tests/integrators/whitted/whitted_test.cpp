#include "hikari/integrators/whitted/whitted.h"

#include <cmath>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "../../io/scene_test_util.h"
#include "hikari/io/scene/scene_json.h"

namespace hikari {
namespace {

using testing::parse;

/// The assignment's colour at pixel (i, j), computed independently in double precision.
std::array<double, 3> assignment_pixel(int i, int j) {
    const double w = 512, h = 512, tan_half = std::tan(M_PI / 6);
    double d[3] = {(2 * (i + 0.5) / w - 1) * tan_half, (1 - 2 * (j + 0.5) / h) * tan_half, -1};
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + 1);
    for (double& c : d) c /= len;
    // |t d − S|² = 1 with S = (0, 0, −3): t² − 2 t (d·S) + 9 − 1 = 0.
    const double b = -3 * d[2];
    const double disc = b * b - 8;
    if (disc < 0) return {0.1, 0.1, 0.1};
    const double t = b - std::sqrt(disc);
    const double n[3] = {t * d[0], t * d[1], t * d[2] + 3};
    const double s3 = std::sqrt(3.0);
    const double l[3] = {-1 / s3, 1 / s3, 1 / s3};  // toward the light
    const double ndotl = n[0] * l[0] + n[1] * l[1] + n[2] * l[2];
    const double kd[3] = {0.8, 0.3, 0.2};
    std::array<double, 3> c;
    double spec = 0;
    if (ndotl > 0) {
        double r[3];
        for (int k = 0; k < 3; ++k) r[k] = -l[k] + 2 * ndotl * n[k];
        const double rv = -(r[0] * d[0] + r[1] * d[1] + r[2] * d[2]);
        spec = rv > 0 ? 0.6 * std::pow(rv, 40) : 0;
    }
    for (int k = 0; k < 3; ++k) c[k] = 0.1 * kd[k] + (ndotl > 0 ? kd[k] * ndotl + spec : 0);
    return c;
}

TEST(Whitted, AssignmentMatchesAnalyticRender) {
    const Scene scene = load_default_scene();
    const Framebuffer fb = render_whitted(scene, Film(scene.camera));
    ASSERT_EQ(fb.width(), 512);
    ASSERT_EQ(fb.height(), 512);
    double worst = 0;
    for (int j = 0; j < 512; ++j)
        for (int i = 0; i < 512; ++i) {
            const auto expected = assignment_pixel(i, j);
            const Vec3 got = fb.film.linear().at(i, j);
            for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(got[k] - expected[k]));
        }
    EXPECT_LT(worst, 1e-4);
}

TEST(Whitted, PointLightFallsOffWithDistanceSquared) {
    // Looking straight down at a Lambert floor with a point light straight above the pixel.
    auto floor_under_light = [](float height) {
        const std::string json = R"({
          "camera": {"eye": [0, 1, 0], "look_at": [0, 0, 0], "up": [0, 0, -1], "fov_y": 10,
                     "width": 3, "height": 3},
          "materials": {"white": {"kd": [1, 1, 1]}},
          "lights": [{"type": "point", "position": [0, )" +
                                 std::to_string(height) + R"(, 0], "intensity": [4, 4, 4]}],
          "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
                       "material": "white"}]})";
        const Scene scene = parse(json);
        return render_whitted(scene, Film(scene.camera)).film.linear().at(1, 1).x;
    };
    EXPECT_NEAR(floor_under_light(2), 4.0f / 4.0f, 1e-5);
    EXPECT_NEAR(floor_under_light(4), 4.0f / 16.0f, 1e-5);
}

const char* k_shadow_scene = R"({
  "camera": {"eye": [0, 2, 6], "look_at": [0, 0.5, 0], "fov_y": 50, "width": 64, "height": 48},
  "background": [0.2, 0.3, 0.5], "ambient": [0.05, 0.05, 0.05],
  "materials": {
    "floor": {"ka": [1, 1, 1], "kd": [0.8, 0.8, 0.8]},
    "red": {"ka": [1, 0, 0], "kd": [0.9, 0.1, 0.1], "ks": [0.5, 0.5, 0.5], "shininess": 30},
    "mirror": {"reflectivity": 1},
    "glass": {"ks": [0.5, 0.5, 0.5], "shininess": 100, "transparency": 0.9, "reflectivity": 0.1,
              "ior": 1.5}
  },
  "lights": [{"type": "point", "position": [2, 5, 3], "intensity": [30, 30, 30]}],
  "objects": [
    {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
    {"type": "sphere", "center": [-1.2, 1, 0], "radius": 1, "material": "mirror"},
    {"type": "sphere", "center": [1.2, 0.7, 0.5], "radius": 0.7, "material": "red"},
    {"type": "sphere", "center": [0, 0.5, 2], "radius": 0.5, "material": "glass"}
  ]})";

TEST(Whitted, SameImageForAnyThreadCount) {
    const Scene scene = parse(k_shadow_scene);
    WhittedSettings settings;
    settings.samples_per_pixel = 4;
    Framebuffer one, two;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = render_whitted(scene, Film(scene.camera), {}, settings);
    }
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        two = render_whitted(scene, Film(scene.camera), {}, settings);
    }
    ASSERT_EQ(one.film.linear().pixels.size(), two.film.linear().pixels.size());
    for (size_t i = 0; i < one.film.linear().pixels.size(); ++i) {
        ASSERT_EQ(one.film.linear().pixels[i], two.film.linear().pixels[i]) << "pixel " << i;
        ASSERT_EQ(one.id[i], two.id[i]);
    }
}

TEST(Whitted, ShadowedPointGetsOnlyAmbient) {
    // A small sphere directly between the light and the floor point under it.
    const Scene scene = parse(R"({
      "camera": {"eye": [0, 1, 0], "look_at": [0, 0, 0], "up": [0, 0, -1], "fov_y": 10,
                 "width": 3, "height": 3},
      "ambient": [0.25, 0.25, 0.25],
      "materials": {"white": {"ka": [1, 1, 1], "kd": [1, 1, 1]}},
      "lights": [{"type": "directional", "direction": [0, -1, 0], "intensity": [1, 1, 1]}],
      "objects": [
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "white"},
        {"type": "sphere", "center": [0, 5, 0], "radius": 0.1, "material": "white"}]})");
    // The sphere is above the camera (y = 5 > 1), so the camera sees the shadowed floor.
    EXPECT_NEAR(render_whitted(scene, Film(scene.camera)).film.linear().at(1, 1).x, 0.25f, 1e-6);
}

TEST(Whitted, PerfectMirrorShowsWhatItReflects) {
    // A mirror floor under a camera looking down reflects the background (the sky) exactly.
    const Scene scene = parse(R"({
      "camera": {"eye": [0, 1, 0], "look_at": [0, 0, 0], "up": [0, 0, -1], "fov_y": 10,
                 "width": 3, "height": 3},
      "background": [0.3, 0.6, 0.9],
      "materials": {"mirror": {"reflectivity": 1}},
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
                   "material": "mirror"}]})");
    const Framebuffer fb = render_whitted(scene, Film(scene.camera));
    EXPECT_NEAR(fb.film.linear().at(1, 1).x, 0.3f, 1e-6);
    EXPECT_NEAR(fb.film.linear().at(1, 1).z, 0.9f, 1e-6);
    WhittedSettings no_bounce;
    no_bounce.max_depth = 1;  // the primary ray only: the mirror shows black
    EXPECT_EQ(render_whitted(scene, Film(scene.camera), {}, no_bounce).film.linear().at(1, 1),
              Vec3(0.0f));
}

TEST(Whitted, AovsDescribeThePixelCentre) {
    const Scene scene = parse(k_shadow_scene);
    WhittedSettings settings;
    settings.samples_per_pixel = 3;
    const Framebuffer fb = render_whitted(scene, Film(scene.camera), {}, settings);
    EXPECT_EQ(fb.id[0], 0u);  // top-left corner: sky
    EXPECT_TRUE(std::isinf(fb.depth[0]));
    const size_t bottom = static_cast<size_t>(47) * 64 + 32;  // bottom centre: the floor
    EXPECT_EQ(fb.id[bottom], 1u);
    EXPECT_GT(fb.depth[bottom], 0.0f);
}

TEST(Whitted, AnEdgeOnTriangleThroughTheEyeIsNotSeen) {
    // The triangle's plane contains the eye: every camera ray crosses it at the eye, where no
    // surface can be seen (issue 28: 1,031 of 9,216 pixels used to come out as speckles).
    const Scene scene = parse(R"({
      "camera": {"eye": [0.3, 1, 2], "look_at": [0, 0, -1], "fov_y": 60, "width": 96, "height": 96},
      "materials": {"grey": {"kd": 0.5}},
      "objects": [{"type": "triangle", "vertices": [[-20, 1, 22], [20, 1, 22], [0.3, 1, -30]], "material": "grey"},
                  {"type": "sphere", "center": [0, 0, -1], "radius": 0.5, "material": "grey"}]})");
    const Framebuffer fb = render_whitted(scene, Film(scene.camera, FilmFormat::linear));
    int seen = 0, sphere = 0;
    for (const uint32_t id : fb.id) {
        seen += id == 1 ? 1 : 0;
        sphere += id == 2 ? 1 : 0;
    }
    EXPECT_EQ(seen, 0);
    EXPECT_GT(sphere, 100);
}

}  // namespace
}  // namespace hikari
