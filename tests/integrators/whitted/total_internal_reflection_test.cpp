// Total internal reflection is exact at any depth: a ray trapped in a glass sphere by TIR keeps
// its angle on every bounce (a sphere's chords all meet it at the same angle), so it must never
// leave, however many times it is reflected.
#include <cmath>

#include <gtest/gtest.h>

#include "../../io/scene_test_util.h"
#include "hikari/bvh/scene_intersector.h"
#include "hikari/integrators/whitted/whitted_surface.h"

namespace hikari {
namespace {

TEST(TotalInternalReflection, ATrappedRayNeverLeavesTheSphere) {
    const Scene scene = testing::parse(R"({
      "materials": {"glass": {"transparency": 1, "ior": 1.5}},
      "objects": [{"type": "sphere", "center": [0.3, -0.2, 0.1], "radius": 1.7, "material": "glass"}]})");
    const SceneIntersector intersector(scene);
    const Sphere& sphere = scene.spheres[0];
    for (int start = 0; start < 50; ++start) {
        // From a point inside, nearly along the surface: far above the critical angle.
        const float a = 0.37f * static_cast<float>(start);
        Ray ray{sphere.center + Vec3(0.93f * sphere.radius * std::cos(a),
                                     0.93f * sphere.radius * std::sin(a), 0.05f),
                normalize(Vec3(-std::sin(a), std::cos(a), 0.2f))};
        for (int bounce = 0; bounce < 1000; ++bounce) {
            SurfaceHit hit;
            ASSERT_TRUE(intersector.closest(ray, {0.0f, k_infinity}, hit))
                << "start " << start << " escaped at bounce " << bounce;
            ASSERT_LT(length(hit.position - sphere.center), sphere.radius * 1.0001f);
            WhittedHit<float> h{ray.direction, hit.position, hit.geometric_normal,
                                hit.shading_normal, static_cast<int32_t>(hit.material)};
            WhittedShading<float> shaded;
            shaded.point = face_the_ray(h, shaded.entering);
            ASSERT_FALSE(shaded.entering) << "start " << start << " bounce " << bounce;
            shaded.material.transparency = 1.0f;
            shaded.material.ior = 1.5f;
            const SecondaryRays<float> rays = whitted_secondary_rays(shaded, ray.direction, true);
            ASSERT_EQ(rays.refract_weight, 0.0f) << "start " << start << " bounce " << bounce;
            ASSERT_EQ(rays.mirror_weight, 1.0f);
            // The mirror ray starts inside, and it is unit length.
            ASSERT_LT(length(rays.mirror_origin - sphere.center), sphere.radius)
                << "start " << start << " bounce " << bounce;
            ASSERT_NEAR(length(rays.mirror_direction), 1.0f, 1e-6f);
            ray = {rays.mirror_origin, rays.mirror_direction};
        }
    }
}

}  // namespace
}  // namespace hikari
