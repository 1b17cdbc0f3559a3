// The light-transport BSDF: each sampling routine checked against its own pdf by a chi-square
// test, the normalized Phong lobe's energy, the Lambert lobe's albedo, and the dielectric's
// Fresnel split.
#include "hikari/shading/bsdf/scattering.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "../../support/pi.h"
#include "hikari/core/rng.h"

namespace hikari {
namespace {

using testing::k_pi_f;

MaterialSample<float> material(Vec3 kd, Vec3 ks, float n, float mirror = 0, float glass = 0,
                               float ior = 1.5f) {
    MaterialSample<float> m;
    m.kd = kd;
    m.ks = ks;
    m.shininess = n;
    m.exponent = phong_integer_exponent(n);
    m.reflectivity = mirror;
    m.transparency = glass;
    m.ior = ior;
    return m;
}

/// A frame with normal +z and the eye at `degrees` from it.
ScatterFrame frame_at(float degrees) {
    const float a = degrees * k_pi_f / 180.0f;
    ScatterFrame at;
    at.to_eye = {std::sin(a), 0.0f, std::cos(a)};
    at.normal = at.geometric_normal = {0.0f, 0.0f, 1.0f};
    return at;
}

/// The direction with cos θ = z and azimuth φ about +z.
Vec3 direction(float z, float phi) {
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

/// The chi-square statistic and its critical value (significance 0.001) for the directions
/// `bsdf.sample` draws against the density `bsdf.evaluate` reports, over equal-solid-angle bins
/// of the sphere (z × φ); bins expecting fewer than 5 samples are pooled.
void expect_sampling_matches_pdf(const Scattering& bsdf, const ScatterFrame& at) {
    // Each bin's expected count by a midpoint rule fine in z, where narrow lobes change fastest.
    constexpr int k_z = 16, k_phi = 32, k_samples = 400000, k_sub_z = 64, k_sub = 6;
    std::vector<double> observed(k_z * k_phi, 0.0), expected(k_z * k_phi, 0.0);
    Pcg32 rng(7, 11);
    for (int i = 0; i < k_samples; ++i) {
        const float u_lobe = rng.next_float();
        const Vec2 u{rng.next_float(), rng.next_float()};
        const ScatterSample s = bsdf.sample(at, u_lobe, u);
        if (s.delta || !(max_component(s.weight) > 0.0f)) continue;
        const Vec3 d = s.direction;
        float phi = std::atan2(d.y, d.x);
        if (phi < 0.0f) phi += 2.0f * k_pi_f;
        const int zi = std::clamp(static_cast<int>((d.z + 1.0f) * 0.5f * k_z), 0, k_z - 1);
        const int pi = std::clamp(static_cast<int>(phi / (2.0f * k_pi_f) * k_phi), 0, k_phi - 1);
        observed[zi * k_phi + pi] += 1.0;
        // The pdf the sample reports is the one evaluate gives for its direction.
        float pdf = 0.0f;
        bsdf.evaluate(at, d, pdf);
        ASSERT_NEAR(pdf, s.pdf, 1e-3f * std::max(1.0f, pdf));
    }
    const double bin_area = (2.0 / k_z) * (2.0 * k_pi_f / k_phi) / (k_sub_z * k_sub);
    for (int zi = 0; zi < k_z; ++zi)
        for (int pi = 0; pi < k_phi; ++pi)
            for (int a = 0; a < k_sub_z; ++a)
                for (int b = 0; b < k_sub; ++b) {
                    const float z = -1.0f + 2.0f * (zi + (a + 0.5f) / k_sub_z) / k_z;
                    const float phi = 2.0f * k_pi_f * (pi + (b + 0.5f) / k_sub) / k_phi;
                    float pdf = 0.0f;
                    bsdf.evaluate(at, direction(z, phi), pdf);
                    expected[zi * k_phi + pi] += pdf * bin_area * k_samples;
                }
    double chi2 = 0.0, pooled_o = 0.0, pooled_e = 0.0;
    int bins = 0;
    for (size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] < 5.0) {
            pooled_o += observed[i];
            pooled_e += expected[i];
            continue;
        }
        chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
        ++bins;
    }
    if (pooled_e >= 5.0) {
        chi2 += (pooled_o - pooled_e) * (pooled_o - pooled_e) / pooled_e;
        ++bins;
    } else {
        EXPECT_LT(pooled_o, 20.0) << "samples where the pdf says there are none";
    }
    ASSERT_GT(bins, 10);
    // Wilson–Hilferty: the chi-square quantile for k degrees of freedom, z = 3.09 (p = 0.001).
    const double k = bins - 1;
    const double critical =
        k * std::pow(1.0 - 2.0 / (9.0 * k) + 3.09 * std::sqrt(2.0 / (9.0 * k)), 3.0);
    EXPECT_LT(chi2, critical) << bins << " bins";
}

TEST(Scattering, LambertSamplingMatchesItsPdf) {
    expect_sampling_matches_pdf(Scattering(material(Vec3(0.8f), Vec3(0.0f), 1.0f), 1.0f),
                                frame_at(30.0f));
}

TEST(Scattering, NormalizedPhongSamplingMatchesItsPdf) {
    for (float n : {1.0f, 8.0f, 40.0f})
        for (float angle : {0.0f, 45.0f, 80.0f}) {
            SCOPED_TRACE(::testing::Message() << "n " << n << " at " << angle << " degrees");
            expect_sampling_matches_pdf(Scattering(material(Vec3(0.0f), Vec3(0.9f), n), 1.0f),
                                        frame_at(angle));
        }
}

TEST(Scattering, MixtureSamplingMatchesItsPdf) {
    expect_sampling_matches_pdf(
        Scattering(material(Vec3(0.3f, 0.2f, 0.1f), Vec3(0.5f), 12.5f, 0.1f), 1.0f),
        frame_at(60.0f));
}

/// ∫ f cos θ dω over the hemisphere by the midpoint rule in (cos θ, φ): the fraction of light
/// arriving from the eye's direction that the smooth lobes send on.
double albedo(const Scattering& bsdf, const ScatterFrame& at) {
    constexpr int k_z = 800, k_phi = 400;
    double sum = 0.0;
    for (int i = 0; i < k_z; ++i)
        for (int j = 0; j < k_phi; ++j) {
            const float z = (i + 0.5f) / k_z, phi = 2.0f * k_pi_f * (j + 0.5f) / k_phi;
            float pdf = 0.0f;
            sum += bsdf.evaluate(at, direction(z, phi), pdf).x * z;
        }
    return sum * (1.0 / k_z) * (2.0 * k_pi_f / k_phi);
}

TEST(Scattering, NormalizedPhongNeverReflectsMoreThanItReceives) {
    for (float n : {0.0f, 1.0f, 2.0f, 5.0f, 20.0f, 100.0f})
        for (float angle : {0.0f, 30.0f, 60.0f, 85.0f}) {
            const double a =
                albedo(Scattering(material(Vec3(0.0f), Vec3(1.0f), n), 1.0f), frame_at(angle));
            EXPECT_LE(a, 1.0 + 2e-3) << "n " << n << " at " << angle << " degrees";
            // Along the normal the whole lobe is above the horizon: exactly ks.
            if (angle == 0.0f) EXPECT_NEAR(a, 1.0, 5e-3) << "n " << n;
        }
}

TEST(Scattering, LambertReflectsItsAlbedo) {
    EXPECT_NEAR(albedo(Scattering(material(Vec3(0.6f), Vec3(0.0f), 1.0f), 1.0f), frame_at(50.0f)),
                0.6, 1e-3);
    // Cosine sampling makes every sample's weight exactly kd.
    const Scattering lambert(material(Vec3(0.6f, 0.5f, 0.4f), Vec3(0.0f), 1.0f), 1.0f);
    const ScatterSample s = lambert.sample(frame_at(10.0f), 0.3f, {0.2f, 0.7f});
    EXPECT_NEAR(s.weight.x, 0.6f, 1e-5f);
    EXPECT_NEAR(s.weight.z, 0.4f, 1e-5f);
}

TEST(Scattering, EnergyScaleBringsAnOverfullMaterialToOne) {
    EXPECT_FLOAT_EQ(scattered_fraction(Vec3(0.7f), Vec3(0.5f), 0.2f, 0.0f), 1.4f);
    const double a =
        albedo(Scattering(material(Vec3(0.7f), Vec3(0.5f), 1.0f), 1.0f / 1.2f), frame_at(0.0f));
    EXPECT_NEAR(a, 1.0, 5e-3);
}

TEST(Scattering, DielectricSplitsByFresnel) {
    float cos_t = 0.0f;
    // Normal incidence on glass: ((1 − 1.5) / (1 + 1.5))² = 0.04.
    EXPECT_NEAR(fresnel_dielectric(1.0f, 1.0f / 1.5f, cos_t), 0.04f, 1e-6f);
    EXPECT_NEAR(cos_t, 1.0f, 1e-6f);
    // From inside beyond the critical angle (41.8°): total internal reflection.
    EXPECT_EQ(fresnel_dielectric(std::cos(50.0f * k_pi_f / 180.0f), 1.5f, cos_t), 1.0f);
    // Grazing: everything is reflected.
    EXPECT_NEAR(fresnel_dielectric(1e-4f, 1.0f / 1.5f, cos_t), 1.0f, 1e-3f);

    const Scattering glass(material(Vec3(0.0f), Vec3(0.0f), 1.0f, 0.0f, 1.0f, 1.5f), 1.0f);
    ScatterFrame at = frame_at(0.0f);
    const ScatterSample reflected = glass.sample(at, 0.01f, {0.5f, 0.5f});
    EXPECT_TRUE(reflected.delta);
    EXPECT_NEAR(reflected.direction.z, 1.0f, 1e-6f);
    EXPECT_FLOAT_EQ(reflected.weight.x, 1.0f);
    const ScatterSample refracted = glass.sample(at, 0.5f, {0.5f, 0.5f});
    EXPECT_NEAR(refracted.direction.z, -1.0f, 1e-6f);
    // Entering glass, radiance is divided by n² (and multiplied back on the way out).
    EXPECT_NEAR(refracted.weight.x, 1.0f / (1.5f * 1.5f), 1e-6f);
    at.entering = false;
    EXPECT_NEAR(glass.sample(at, 0.5f, {0.5f, 0.5f}).weight.x, 1.5f * 1.5f, 1e-5f);
    // Snell at 45° into glass: sin θ_t = sin 45° / 1.5.
    at = frame_at(45.0f);
    const ScatterSample bent = glass.sample(at, 0.9f, {0.5f, 0.5f});
    EXPECT_NEAR(std::hypot(bent.direction.x, bent.direction.y), std::sin(k_pi_f / 4) / 1.5f, 1e-5f);
}

TEST(Scattering, MirrorAndBlackSurfaces) {
    const Scattering mirror(material(Vec3(0.0f), Vec3(0.0f), 1.0f, 0.8f), 1.0f);
    EXPECT_FALSE(mirror.smooth());
    const ScatterSample s = mirror.sample(frame_at(30.0f), 0.5f, {0.1f, 0.1f});
    EXPECT_TRUE(s.delta);
    EXPECT_NEAR(s.direction.x, -std::sin(k_pi_f / 6), 1e-6f);
    EXPECT_FLOAT_EQ(s.weight.y, 0.8f);
    EXPECT_TRUE(Scattering(material(Vec3(0.0f), Vec3(0.0f), 1.0f), 1.0f).black());
}

}  // namespace
}  // namespace hikari
