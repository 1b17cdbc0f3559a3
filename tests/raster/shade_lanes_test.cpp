#include "hikari/raster/shade_lanes.h"

#include <gtest/gtest.h>

#include <vector>

#include "hikari/core/rng.h"
#include "hikari/shading/direct.h"
#include "hikari/shading/material_eval.h"

namespace hikari {
namespace {

/// The fraction of light `l` that reaches lane k in these tests: blocked, half or whole.
float test_fraction(size_t l, int k) {
    return static_cast<float>((k + static_cast<int>(l)) % 3) * 0.5f;
}

void test_fractions(const void*, size_t light, int first, uint32_t lanes, float* fraction) {
    for (int j = 0; j < 32; ++j)
        if (lanes >> j & 1u) fraction[j] = test_fraction(light, first + j);
}

Vec3 unit_random(Pcg32& rng) {
    const Vec3 v(2 * rng.next_float() - 1, 2 * rng.next_float() - 1, 2 * rng.next_float() - 1);
    return normalize(v + Vec3(0.0f, 0.0f, 0.01f));
}

TEST(ShadeLanes, EveryLaneIsTheOnePointColour) {
    // Random points, normals and two materials under a point and a directional light, each lane's
    // light let through in part: every kernel gives, bit for bit, what direct_lighting<float>
    // gives one point at a time with the same fractions.
    std::vector<Material> materials(2);
    materials[0].ka = Vec3(0.2f, 0.3f, 0.4f), materials[0].kd = Vec3(0.6f, 0.5f, 0.4f);
    materials[0].ks = Vec3(0.3f), materials[0].shininess = 20.0f;
    materials[1].ka = Vec3(0.1f), materials[1].kd = Vec3(0.2f, 0.7f, 0.3f);
    const std::vector<Light> lights = {
        PointLight{Vec3(2.0f, 3.0f, 1.0f), Vec3(5.0f, 4.0f, 3.0f)},
        DirectionalLight{normalize(Vec3(1.0f, -1.0f, -0.5f)), Vec3(0.7f)}};
    LaneLighting lighting;
    lighting.lighting = {lights.data(), lights.size(), Vec3(0.3f)};
    lighting.materials = materials.data();
    lighting.fractions = &test_fractions;
    constexpr int k_count = 101;  // not a whole number of lane groups
    SurfaceLanes lanes{};
    Pcg32 rng(3, 5);
    for (int k = 0; k < 112; ++k) {
        const Vec3 p(rng.next_float(), rng.next_float(), rng.next_float());
        const Vec3 n = unit_random(rng), e = unit_random(rng);
        for (int a = 0; a < 3; ++a) {
            lanes.position[a][k] = p[a];
            lanes.normal[a][k] = n[a];
            lanes.to_eye[a][k] = e[a];
        }
        lanes.material[k] = k % 3 == 0 ? 1 : 0;
    }
    for (const SimdLevel level : supported_simd_levels()) {
        shade_surface_lanes(lighting, k_count, lanes, level);
        for (int k = 0; k < k_count; ++k) {
            SurfacePoint<float> s;
            s.position = Vec3(lanes.position[0][k], lanes.position[1][k], lanes.position[2][k]);
            s.normal = Vec3(lanes.normal[0][k], lanes.normal[1][k], lanes.normal[2][k]);
            s.geometric_normal = s.normal;
            s.to_eye = Vec3(lanes.to_eye[0][k], lanes.to_eye[1][k], lanes.to_eye[2][k]);
            const MaterialSample<float> m =
                evaluate_material<float>(materials.data(), lanes.material[k], s);
            const auto visible = [&](size_t l, const LightSample&, const SurfacePoint<float>&,
                                     bool) { return test_fraction(l, k); };
            const Vec3 one = direct_lighting<float>(lighting.lighting, s, m, true, visible).colour;
            EXPECT_EQ(lanes.colour[0][k], one.x) << simd_level_name(level) << " lane " << k;
            EXPECT_EQ(lanes.colour[1][k], one.y) << simd_level_name(level) << " lane " << k;
            EXPECT_EQ(lanes.colour[2][k], one.z) << simd_level_name(level) << " lane " << k;
            EXPECT_EQ(lanes.scalar_only[k], 0);
        }
    }
}

TEST(ShadeLanes, VertexColoursAreLeftToTheOnePointCode) {
    std::vector<Material> materials(1);
    materials[0].kd = Vec3(0.5f);
    materials[0].vertex_colours = true;
    const std::vector<Light> lights = {DirectionalLight{Vec3(0.0f, 0.0f, -1.0f), Vec3(1.0f)}};
    LaneLighting lighting;
    lighting.lighting = {lights.data(), lights.size(), Vec3(0.0f)};
    lighting.materials = materials.data();
    SurfaceLanes lanes{};
    for (int k = 0; k < SurfaceLanes::k_lane_group; ++k) {
        lanes.normal[2][k] = 1.0f;
        lanes.to_eye[2][k] = 1.0f;
    }
    shade_surface_lanes(lighting, 5, lanes);
    for (int k = 0; k < 5; ++k) EXPECT_EQ(lanes.scalar_only[k], 1);
}

}  // namespace
}  // namespace hikari
