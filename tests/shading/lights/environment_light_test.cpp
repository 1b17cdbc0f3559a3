// Environment lights: the latitude–longitude map's orientation and importance sampling
// (scene/environment_map.h, core/piecewise_constant.h), the sampling routine
// (shading/lights/environment_light.h) and the spherical-harmonic irradiance the rasterizer
// uses (shading/spherical_harmonics.h).
#include "hikari/scene/environment_map.h"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "../../support/pi.h"
#include "hikari/core/piecewise_constant.h"
#include "hikari/core/rng.h"
#include "hikari/shading/lights/environment_light.h"
#include "hikari/shading/spherical_harmonics.h"

namespace hikari {
namespace {

using testing::k_pi;

/// A 2:1 map: a bright blob toward +x a little above the horizon on a dim sky, ground darker.
Image test_sky(int height) {
    Image image(2 * height, height);
    const EnvironmentMap frame(Image(2 * height, height), 0.0f);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < 2 * height; ++x) {
            const Vec3 d = frame.direction_of({(x + 0.5f) / (2 * height), (y + 0.5f) / height});
            const float blob =
                std::pow(std::max(0.0f, dot(d, normalize(Vec3(1, 0.4f, 0.2f)))), 30.0f);
            image.at(x, y) = d.y > 0 ? Vec3(0.3f, 0.4f, 0.6f) + Vec3(8, 7, 5) * blob : Vec3(0.1f);
        }
    return image;
}

TEST(PiecewiseConstant, SamplesFollowTheWeights) {
    const std::vector<float> weights = {1, 0, 3, 4, 0, 0, 2, 6};  // 4 x 2
    const PiecewiseConstant2D d(weights, 4, 2);
    std::vector<int> counts(8, 0);
    Pcg32 rng(7, 1);
    constexpr int n = 160000;
    for (int i = 0; i < n; ++i) {
        float pdf = 0;
        const Vec2 uv = d.sample({rng.next_float(), rng.next_float()}, pdf);
        EXPECT_NEAR(pdf, d.pdf(uv), 1e-4f);
        ++counts[static_cast<int>(uv.y * 2) * 4 + static_cast<int>(uv.x * 4)];
    }
    for (size_t c = 0; c < 8; ++c)
        EXPECT_NEAR(counts[c] / double(n), weights[c] / 16.0, 0.005) << c;
}

TEST(EnvironmentMap, OrientationIsTheDocumentedOne) {
    const EnvironmentMap map(Image(64, 32), 0.0f);
    const auto near = [](Vec3 a, Vec3 b) { return length(a - b) < 1e-5f; };
    EXPECT_TRUE(near(map.direction_of({0.5f, 0.5f}), {0, 0, -1}));  // middle column: −z
    EXPECT_TRUE(near(map.direction_of({0.75f, 0.5f}), {1, 0, 0}));  // right: +x
    EXPECT_TRUE(near(map.direction_of({0.25f, 0.5f}), {-1, 0, 0}));
    EXPECT_NEAR(map.direction_of({0.3f, 0.0f}).y, 1.0f, 1e-6f);  // row 0: zenith
    const EnvironmentMap turned(Image(64, 32), 90.0f);           // counter-clockwise from above
    EXPECT_TRUE(near(turned.direction_of({0.5f, 0.5f}), {-1, 0, 0}));
    Pcg32 rng(3, 3);
    for (int i = 0; i < 100; ++i) {
        const Vec2 uv{rng.next_float(), 0.01f + 0.98f * rng.next_float()};
        const Vec2 back = turned.uv_of(turned.direction_of(uv));
        EXPECT_NEAR(back.x, uv.x, 1e-4f);
        EXPECT_NEAR(back.y, uv.y, 1e-4f);
    }
}

TEST(EnvironmentMap, ImportanceSamplingIsUnbiased) {
    const EnvironmentMap map(test_sky(32), 30.0f);
    // ∫ L dω exactly: each texel's radiance times its solid angle.
    const Image& img = map.image();
    double exact = 0;
    for (int y = 0; y < img.height; ++y) {
        const double d_omega =
            (2 * k_pi / img.width) * (k_pi / img.height) * std::sin(k_pi * (y + 0.5) / img.height);
        for (int x = 0; x < img.width; ++x) exact += img.at(x, y).y * d_omega;
    }
    Pcg32 rng(11, 5);
    double sum = 0;
    int other_texel = 0;  // samples on a texel's edge may look up its neighbour's density
    constexpr int n = 200000;
    for (int i = 0; i < n; ++i) {
        const EnvironmentDirection s = map.sample({rng.next_float(), rng.next_float()});
        ASSERT_GT(s.pdf, 0.0f);
        other_texel += std::abs(s.pdf - map.pdf(s.direction)) > 2e-3f * s.pdf;
        EXPECT_EQ(s.radiance, map.radiance_from(s.direction));
        sum += s.radiance.y / s.pdf;
    }
    EXPECT_LT(other_texel, n / 1000);
    EXPECT_NEAR(sum / n, exact, 0.01 * exact);
}

TEST(EnvironmentLight, ConstantRadianceGivesPiLOnEverySample) {
    const EnvironmentLight light{Vec3(0.5f, 1.0f, 2.0f)};
    const Vec3 n = normalize(Vec3(0.3f, 0.8f, -0.2f));
    Pcg32 rng(1, 2);
    for (int i = 0; i < 200; ++i) {
        const LightSample s = sample_environment(light, n, rng.next_float(), rng.next_float());
        const float cos_theta = dot(n, s.to_light);
        ASSERT_GT(cos_theta, 0.0f);
        // Cosine-weighted: irradiance · cos θ is π L for every direction.
        EXPECT_NEAR(s.irradiance.z * cos_theta, k_pi * 2.0, 1e-4);
    }
}

TEST(SphericalHarmonics, IrradianceOfAConstantIsPiL) {
    const IrradianceSh sh = project_environment(EnvironmentLight{Vec3(0.25f)});
    for (const Vec3 n : {Vec3(0, 1, 0), Vec3(1, 0, 0), normalize(Vec3(-1, -2, 3))})
        EXPECT_NEAR(sh.irradiance(n).x, 0.25 * k_pi, 1e-5);
}

TEST(SphericalHarmonics, IrradianceMatchesDirectIntegration) {
    EnvironmentLight light;
    light.map = std::make_shared<const EnvironmentMap>(test_sky(64), 0.0f);
    const IrradianceSh sh = project_environment(light);
    const Image& img = light.map->image();
    Pcg32 rng(5, 9);
    double err2 = 0, ref2 = 0;
    for (int k = 0; k < 24; ++k) {
        Vec3 n;
        do n = {2 * rng.next_float() - 1, 2 * rng.next_float() - 1, 2 * rng.next_float() - 1};
        while (dot(n, n) > 1 || dot(n, n) < 0.01f);
        n = normalize(n);
        double e = 0;
        for (int y = 0; y < img.height; ++y) {
            const double v = (y + 0.5) / img.height;
            const double d_omega =
                (2 * k_pi / img.width) * (k_pi / img.height) * std::sin(k_pi * v);
            for (int x = 0; x < img.width; ++x) {
                const Vec3 d =
                    light.map->direction_of({(x + 0.5f) / img.width, static_cast<float>(v)});
                e += img.at(x, y).y * std::max(0.0f, dot(n, d)) * d_omega;
            }
        }
        const double approx = sh.irradiance(n).y;
        err2 += (approx - e) * (approx - e);
        ref2 += e * e;
    }
    // Bands 0–2 keep all but a few per cent of the irradiance (Ramamoorthi & Hanrahan 2001).
    EXPECT_LT(std::sqrt(err2 / ref2), 0.05);
}

}  // namespace
}  // namespace hikari
