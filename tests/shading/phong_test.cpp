#include "hikari/shading/phong.h"

#include <cmath>

#include <gtest/gtest.h>

#include "hikari/shading/direct.h"
#include "hikari/shading/material_eval.h"

namespace hikari {
namespace {

Material clay() {
    Material m;
    m.ka = {0.8f, 0.3f, 0.2f};
    m.kd = {0.8f, 0.3f, 0.2f};
    m.ks = Vec3(0.6f);
    m.shininess = 40;
    return m;
}

/// The light reflected toward `v` from one light arriving from direction `l` with irradiance
/// `irradiance` at a surface of normal `n`, through shading/direct.h (no ambient light).
Vec3 shade_direct(const Material& m, Vec3 n, Vec3 l, Vec3 v, Vec3 irradiance) {
    const Light light = DirectionalLight{-l, irradiance};
    SurfacePoint<float> s;
    s.normal = s.geometric_normal = n;
    s.to_eye = v;
    const MaterialSample<float> sample = evaluate_material<float>(&m, 0, s);
    const auto lit = [](size_t, const LightSample&, const SurfacePoint<float>&, bool) {
        return true;
    };
    return direct_lighting<float>({&light, 1, Vec3(0.0f)}, s, sample, true, lit).colour;
}

TEST(Phong, AmbientIsKaTimesIa) {
    const Material m = clay();
    const SurfacePoint<float> s;
    const auto lit = [](size_t, const LightSample&, const SurfacePoint<float>&, bool) {
        return true;
    };
    const Vec3 c = direct_lighting<float>({nullptr, 0, Vec3(0.1f)}, s,
                                          evaluate_material<float>(&m, 0, s), true, lit)
                       .colour;
    EXPECT_FLOAT_EQ(c.x, 0.08f);
    EXPECT_FLOAT_EQ(c.y, 0.03f);
    EXPECT_FLOAT_EQ(c.z, 0.02f);
}

TEST(Phong, DiffuseFollowsLambertCosine) {
    Material m = clay();
    m.ks = Vec3(0.0f);
    const Vec3 n{0, 0, 1};
    const Vec3 l = normalize(Vec3{1, 0, 1});  // 45 degrees
    const Vec3 c = shade_direct(m, n, l, n, Vec3(2.0f));
    EXPECT_NEAR(c.x, 2.0f * 0.8f * std::cos(0.25 * M_PI), 1e-6);
    EXPECT_NEAR(c.z, 2.0f * 0.2f * std::cos(0.25 * M_PI), 1e-6);
}

TEST(Phong, SpecularPeaksAtMirrorDirection) {
    // Light at 30 degrees on one side, eye at 30 degrees on the other: R = V, cos γ = 1.
    const Vec3 n{0, 1, 0};
    const Vec3 l = normalize(Vec3{-1, std::sqrt(3.0f), 0});
    const Vec3 v = normalize(Vec3{1, std::sqrt(3.0f), 0});
    const Material m = clay();
    const Vec3 c = shade_direct(m, n, l, v, Vec3(1.0f));
    const float cos_alpha = std::sqrt(3.0f) / 2.0f;
    EXPECT_NEAR(c.x, 0.8f * cos_alpha + 0.6f, 1e-5);
    EXPECT_NEAR(c.y, 0.3f * cos_alpha + 0.6f, 1e-5);
}

TEST(Phong, ShininessZeroIsOneWhereverTheLightArrives) {
    // max(0, R·V)^0 read literally: 1, also where R·V ≤ 0 (x⁰ = 1), so the "highlight" is the
    // constant ks wherever N·L > 0, not a disc. The eye here looks from the light's side, so
    // R·V < 0.
    Material m = clay();
    m.kd = Vec3(0.0f);
    m.shininess = 0;
    const Vec3 n{0, 1, 0};
    const Vec3 l = normalize(Vec3{-1, 1, 0});
    const Vec3 v = normalize(Vec3{-1, 0.2f, 0});
    EXPECT_NEAR(shade_direct(m, n, l, v, Vec3(1.0f)).x, 0.6f, 1e-6);
    EXPECT_NEAR(shade_direct(m, n, l, n, Vec3(1.0f)).x, 0.6f, 1e-6);
    // With n > 0 the same eye sees none of it.
    m.shininess = 1;
    EXPECT_EQ(shade_direct(m, n, l, v, Vec3(1.0f)).x, 0.0f);
}

TEST(Phong, HandComputedValueAwayFromTheHighlight) {
    // N = +z, L at 60 degrees from N in the xz plane, V straight along N:
    // R = (−sin60, 0, cos60)·(−1, 0, ... ) → R·V = cos 60 = 0.5, so spec = 0.5^n.
    const Vec3 n{0, 0, 1};
    const Vec3 l{std::sin(float(M_PI) / 3), 0, std::cos(float(M_PI) / 3)};
    Material m = clay();
    m.shininess = 3;
    const Vec3 c = shade_direct(m, n, l, n, Vec3(1.0f));
    EXPECT_NEAR(c.x, 0.8f * 0.5f + 0.6f * 0.125f, 1e-6);
    EXPECT_NEAR(c.z, 0.2f * 0.5f + 0.6f * 0.125f, 1e-6);
}

TEST(Phong, NoLightFromBehind) {
    const Vec3 n{0, 0, 1};
    const Vec3 c = shade_direct(clay(), n, {0, 0, -1}, n, Vec3(1.0f));
    EXPECT_EQ(c, Vec3(0.0f));
    // Grazing light behind the surface while the eye sees the mirror direction: still nothing.
    const Vec3 grazing = normalize(Vec3{1, 0, -1e-3f});
    EXPECT_EQ(shade_direct(clay(), n, grazing, reflect(-grazing, n), Vec3(1.0f)), Vec3(0.0f));
}

TEST(Phong, ReflectMatchesLectureFormula) {
    // R = L + 2aN, a = −L·N
    const Vec3 l = normalize(Vec3{1, -1, -1});
    const Vec3 n = normalize(Vec3{0.2f, 1, 0.3f});
    const float a = -dot(l, n);
    const Vec3 expected = l + 2 * a * n;
    const Vec3 r = reflect(l, n);
    EXPECT_NEAR(r.x, expected.x, 1e-7);
    EXPECT_NEAR(r.y, expected.y, 1e-7);
    EXPECT_NEAR(r.z, expected.z, 1e-7);
    EXPECT_NEAR(length(r), 1.0f, 1e-6);
}

TEST(Phong, PowerMatchesPowWithinNTimesFloatEpsilon) {
    for (float n : {0.0f, 1.0f, 2.0f, 7.0f, 40.0f, 200.0f, 1000.0f, 2.5f, 0.3f, 5000.0f})
        for (float c = 0.001f; c <= 1.0f; c += 0.0137f) {
            const double want = std::pow(static_cast<double>(c), static_cast<double>(n));
            EXPECT_NEAR(phong_power(c, n), want, (n + 2.0) * 1.2e-7 * want + 1e-38)
                << c << "^" << n;
        }
}

}  // namespace
}  // namespace hikari
