#include "hikari/integrators/path/emitters.h"

#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "../../io/scene_test_util.h"
#include "hikari/core/rng.h"

namespace hikari {
namespace {

using testing::parse;

/// A scene with every kind of emitter: an emissive quad (two triangles), an area light, a point
/// light and a constant sky.
Scene every_emitter() {
    return parse(R"({
      "materials": {"lamp": {"emission": [4, 4, 4]}, "grey": {"kd": 0.5}},
      "lights": [{"type": "area", "corner": [-1, 3, -1], "edge1": [2, 0, 0], "edge2": [0, 0, 2], "radiance": 2},
                 {"type": "point", "position": [0, 2, 2], "intensity": 5},
                 {"type": "environment", "radiance": 0.5}],
      "objects": [{"type": "triangle", "vertices": [[2, 1, -1], [2, 1, 1], [2, 3, 1]], "material": "lamp"},
                  {"type": "triangle", "vertices": [[2, 1, -1], [2, 3, 1], [2, 3, -1]], "material": "lamp"},
                  {"type": "triangle", "vertices": [[-5, 0, -5], [-5, 0, 5], [5, 0, 5]], "material": "grey"}]})");
}

TEST(Emitters, SamplesReportTheDensityTheLookupsGive) {
    const Scene scene = every_emitter();
    const EmitterTable table(scene);
    ASSERT_FALSE(table.empty());
    EXPECT_TRUE(table.emits(0));
    EXPECT_FALSE(table.emits(2));
    const Vec3 p{0.0f, 0.5f, 0.0f}, n{0.0f, 1.0f, 0.0f};
    Pcg32 rng(3, 4);
    int kinds_seen[4] = {};
    for (int i = 0; i < 2000; ++i) {
        const float choice = rng.next_float();
        const Vec2 u{rng.next_float(), rng.next_float()};
        const EmitterSample s = table.sample(p, n, choice, u);
        if (!(s.pdf > 0.0f)) continue;
        if (s.delta) {
            ++kinds_seen[0];
            continue;
        }
        // Which emitter the direction leads to decides which lookup must agree.
        float lookup = 0.0f;
        if (std::isinf(s.distance)) {
            lookup = table.environment_pdf(s.to_light, n);
            ++kinds_seen[1];
        } else if (std::abs(p.y + s.to_light.y * s.distance - 3.0f) < 1e-3f &&
                   std::abs(p.x + s.to_light.x * s.distance) < 1.0f + 1e-3f) {
            lookup = table.light_pdf(0, n, s.to_light, s.distance);
            ++kinds_seen[2];
        } else {
            // On the emissive quad at x = 2: which triangle holds the point.
            const Vec3 y = p + s.to_light * s.distance;
            const uint32_t triangle = (y.y - 1.0f) > (y.z + 1.0f) ? 1U : 0U;
            lookup = table.triangle_pdf(triangle, s.to_light, s.distance);
            ++kinds_seen[3];
        }
        EXPECT_NEAR(lookup, s.pdf, 1e-3f * s.pdf) << i;
    }
    for (int k = 0; k < 4; ++k) EXPECT_GT(kinds_seen[k], 20) << "kind " << k;
}

TEST(Emitters, LightSamplingEstimatesTheIrradianceOfAnEmissiveQuad) {
    // A 2×2 emissive square of radiance 4 one unit above a point, facing it: the irradiance
    // E = ∫ L cos θ cos θ′ / r² dA from light sampling and from a fine quadrature.
    const Scene scene = parse(R"({
      "materials": {"lamp": {"emission": 4}},
      "objects": [{"type": "triangle", "vertices": [[-1, 1, -1], [1, 1, -1], [1, 1, 1]], "material": "lamp"},
                  {"type": "triangle", "vertices": [[-1, 1, -1], [1, 1, 1], [-1, 1, 1]], "material": "lamp"}]})");
    const EmitterTable table(scene);
    const Vec3 p{0.0f}, n{0.0f, 1.0f, 0.0f};
    double estimate = 0.0;
    constexpr int k_samples = 64 * 64;
    for (int i = 0; i < k_samples; ++i) {
        const EmitterSample s =
            table.sample(p, n, (i % 2 + 0.5f) / 2.0f,
                         {((i / 2) % 32 + 0.5f) / 32.0f, ((i / 64) + 0.5f) / 64.0f});
        if (s.pdf > 0.0f) estimate += s.radiance.x * dot(n, s.to_light) / s.pdf;
    }
    estimate /= k_samples;
    double exact = 0.0;
    constexpr int k_grid = 400;
    for (int a = 0; a < k_grid; ++a)
        for (int b = 0; b < k_grid; ++b) {
            const double x = -1.0 + 2.0 * (a + 0.5) / k_grid, z = -1.0 + 2.0 * (b + 0.5) / k_grid;
            const double r2 = x * x + 1.0 + z * z;
            exact += 4.0 * (1.0 / std::sqrt(r2)) * (1.0 / std::sqrt(r2)) / r2 *
                     (4.0 / (k_grid * k_grid));
        }
    EXPECT_NEAR(estimate, exact, 0.01 * exact);
}

TEST(Emitters, OneSidedFacesSendNothingBackward) {
    const Scene scene = parse(R"({
      "materials": {"lamp": {"emission": 4}},
      "objects": [{"type": "triangle", "vertices": [[-1, 1, -1], [1, 1, 1], [1, 1, -1]], "material": "lamp"}]})");
    const EmitterTable table(scene);
    // The front of (−1,1,−1), (1,1,1), (1,1,−1) faces +y: a point below sees its back.
    const EmitterSample s = table.sample(Vec3(0.0f), Vec3(0, 1, 0), 0.5f, {0.3f, 0.3f});
    EXPECT_EQ(s.pdf, 0.0f);
    EXPECT_EQ(table.triangle_pdf(0, Vec3(0, 1, 0), 1.0f), 0.0f);
    EXPECT_GT(table.triangle_pdf(0, Vec3(0, -1, 0), 1.0f), 0.0f);
}

TEST(Emitters, ASceneWithoutLightIsEmpty) {
    const Scene scene = parse(R"({
      "materials": {"grey": {"kd": 0.5}},
      "objects": [{"type": "sphere", "center": [0, 0, -3], "radius": 1, "material": "grey"}]})");
    EXPECT_TRUE(EmitterTable(scene).empty());
}

}  // namespace
}  // namespace hikari
