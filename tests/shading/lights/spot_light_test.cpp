// The spot light (scene/light.h): its falloff is the documented smoothstep of cos θ, measured
// on a rendered floor at the cone's edge; every raster method's perspective shadow map of the
// cone agrees with ray tracing's shadow rays; the path tracer's direct light converges to the
// ray tracer's.
#include "hikari/shading/lights/spot_light.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "../../raster/raster_test_util.h"
#include "../../support/pi.h"
#include "hikari/integrators/path/path_tracer.h"
#include "hikari/integrators/whitted/whitted.h"
#include "hikari/methods/registry.h"
#include "hikari/scene/camera.h"
#include "hikari/shading/lights.h"

namespace hikari {
namespace {

/// The documented falloff, written independently of spot_light.h: smoothstep(cos θo, cos θi, c).
double documented_falloff(double cos_theta, double inner_degrees, double outer_degrees) {
    const double ci = std::cos(inner_degrees * testing::k_pi / 180.0);
    const double co = std::cos(outer_degrees * testing::k_pi / 180.0);
    const double t = std::clamp((cos_theta - co) / (ci - co), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

TEST(SpotLight, FullInsideTheInnerConeNoneOutsideTheOuter) {
    const SpotLight spot{Vec3(0, 2, 0), Vec3(0, -1, 0), Vec3(8.0f), 20.0f, 30.0f};
    // Straight below, 2 units: I / d².
    EXPECT_NEAR(sample_light<float>(spot, Vec3(0, 0, 0)).irradiance.x, 2.0f, 1e-6f);
    // 35° off the axis: dark; 10°: full, at its distance.
    const float d35 = 2.0f * std::tan(35.0f * testing::k_pi_f / 180.0f);
    EXPECT_EQ(sample_light<float>(spot, Vec3(d35, 0, 0)).irradiance.x, 0.0f);
    const Vec3 p10(2.0f * std::tan(10.0f * testing::k_pi_f / 180.0f), 0, 0);
    EXPECT_NEAR(sample_light<float>(spot, p10).irradiance.x,
                8.0f / dot(p10 - spot.position, p10 - spot.position), 1e-5f);
}

TEST(SpotLight, EqualAnglesMakeAHardEdge) {
    const SpotLight spot{Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(1.0f), 30.0f, 30.0f};
    const float r = std::tan(30.0f * testing::k_pi_f / 180.0f);
    EXPECT_GT(sample_light<float>(spot, Vec3(0.99f * r, 0, 0)).irradiance.x, 0.5f);
    EXPECT_EQ(sample_light<float>(spot, Vec3(1.01f * r, 0, 0)).irradiance.x, 0.0f);
}

TEST(SpotLight, PowerIsTheIntegralOfTheFalloff) {
    const SpotLight spot{Vec3(0.0f), Vec3(0, 0, 1), Vec3(1.0f), 25.0f, 40.0f};
    // ∫ s(cos θ) dω = 2π ∫ s(c) dc, by the midpoint rule over c.
    const int n = 200000;
    double integral = 0;
    for (int i = 0; i < n; ++i) {
        const double c = -1.0 + 2.0 * (i + 0.5) / n;
        integral += documented_falloff(c, 25.0, 40.0) * 2.0 / n;
    }
    EXPECT_NEAR(light_power(Light(spot), 1.0f), 2.0 * testing::k_pi * integral, 1e-4);
}

/// A white Lambert floor seen straight down under a spot light straight above it, rendered by
/// the ray tracer; each floor pixel's value against kd · I · s(cos θ) · cos θ / d² computed from
/// the camera ray through the pixel centre.
TEST(SpotLight, ConeEdgeOnTheFloorMatchesTheFormula) {
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0, 6, 0], "look_at": [0, 0, 0], "up": [0, 0, -1], "fov_y": 50,
                 "width": 96, "height": 96},
      "materials": {"white": {"ka": [0, 0, 0], "kd": [1, 1, 1]}},
      "lights": [{"type": "spot", "position": [0, 3, 0], "direction": [0, -1, 0],
                  "intensity": [9, 9, 9], "inner_angle": 20, "outer_angle": 35}],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
                   "material": "white"}]})");
    const Framebuffer fb = render_whitted(scene, Film(scene.camera));
    const CameraFrame frame = make_camera_frame(scene.camera);
    int in_band = 0;
    double worst = 0;
    for (int y = 0; y < scene.camera.height; ++y)
        for (int x = 0; x < scene.camera.width; ++x) {
            const Ray ray = camera_ray(frame, x + 0.5f, y + 0.5f);
            const Vec3 p = ray.origin + (-ray.origin.y / ray.direction.y) * ray.direction;
            const Vec3 d = Vec3(0, 3, 0) - p;
            const double d2 = dot(d, d), cos_theta = 3.0 / std::sqrt(d2);
            const double expected = 9.0 * documented_falloff(cos_theta, 20, 35) * cos_theta / d2;
            const double got = fb.film.linear().at(x, y).x;
            worst = std::max(worst, std::abs(got - expected));
            const double theta = std::acos(cos_theta) * 180.0 / testing::k_pi;
            in_band += theta > 21.0 && theta < 34.0 ? 1 : 0;
        }
    EXPECT_GT(in_band, 200);  // the smooth edge is many pixels wide
    EXPECT_LT(worst, 1e-4);
}

/// scenes/light-spot.json at a test's size.
Scene spot_scene() { return testing::scene_file("light-spot.json", 160, 120); }

TEST(SpotLight, EveryRasterMethodAgreesWithRayTracing) {
    const Scene scene = spot_scene();
    const Framebuffer reference = render_whitted(scene, Film(scene.camera));
    int raster_methods = 0;
    for (const Method& method : methods()) {
        if (!does_shadows(method, ShadowMode::map) || method.name == "raytrace") continue;
        ++raster_methods;
        MethodSettings own;
        own.shadows = ShadowMode::map;
        const Framebuffer fb = render_scene(method, scene, Film(scene.camera), {}, own);
        EXPECT_GE(testing::psnr(reference, fb), 35.0) << method.name;
    }
    EXPECT_GE(raster_methods, 4);
}

TEST(SpotLight, PathTracerDirectLightConvergesToRayTracing) {
    // The path tracer's Lambert BRDF is kd / π, the lecture's model kd (docs/path-tracing.md):
    // with the light scaled by π and no bounces the two estimate the same image, the path
    // tracer by sampling the spot light (the only light: chosen every time).
    Scene scene = spot_scene();
    for (Material& m : scene.materials) m.ks = Vec3(0.0f);
    scene.ambient = Vec3(0.0f);
    WhittedSettings whitted;
    whitted.samples_per_pixel = 16;
    const Framebuffer reference = render_whitted(scene, Film(scene.camera), {}, whitted);
    std::get<SpotLight>(scene.lights[0]).intensity *= testing::k_pi_f;
    const auto path = [&](int spp) {
        PathSettings p;
        p.samples_per_pixel = spp;
        p.max_depth = 0;
        return render_path(scene, Film(scene.camera), {}, p);
    };
    const double few = testing::psnr(reference, path(4));
    const double many = testing::psnr(reference, path(64));
    EXPECT_GT(many, 35.0);
    EXPECT_GT(many, few);
}

}  // namespace
}  // namespace hikari
