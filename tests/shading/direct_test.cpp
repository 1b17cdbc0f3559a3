// Direct lighting (shading/direct.h) through the material evaluation (shading/material_eval.h):
// the visibility callable decides which lights count, and a pack of lanes gives, lane by lane,
// the bits the one-point code gives.
#include "hikari/shading/direct.h"

#include <bit>
#include <vector>

#include <gtest/gtest.h>

#include "../support/test_isa16.h"
#include "hikari/core/rng.h"
#include "hikari/shading/material_eval.h"

namespace hikari {
namespace {

using testing::k_lanes16;
using testing::TestIsa16;
using Floats = LaneFloat<TestIsa16>;
using Ints = LaneInt<TestIsa16>;
using Masks = LaneMask<TestIsa16>;

const auto k_all_visible = [](size_t, const auto&, const auto&, const auto&) { return true; };

TEST(DirectLighting, VisibilityDecidesWhichFacingLightsCount) {
    const std::vector<Light> lights = {DirectionalLight{{0, -1, 0}, Vec3(1.0f)},   // from above
                                       DirectionalLight{{0, 1, 0}, Vec3(5.0f)},    // from below
                                       DirectionalLight{{0, -1, 0}, Vec3(2.0f)}};  // blocked
    Material m;
    m.ka = Vec3(0.5f);
    m.kd = Vec3(0.25f);
    SurfacePoint<float> s;
    s.normal = s.geometric_normal = s.to_eye = {0, 1, 0};
    std::vector<size_t> asked;
    const auto visible = [&](size_t l, const LightSample&, const SurfacePoint<float>&, bool) {
        asked.push_back(l);
        return l != 2;
    };
    const DirectLighting<float> d =
        direct_lighting<float>({lights.data(), lights.size(), Vec3(0.1f)}, s,
                               evaluate_material<float>(&m, 0, s), true, visible);
    EXPECT_EQ(asked, (std::vector<size_t>{0, 2}));  // the light from below faces away
    EXPECT_EQ(d.tested, 2);
    EXPECT_FLOAT_EQ(d.colour.x, 0.5f * 0.1f + 0.25f * 1.0f);
}

TEST(DirectLighting, TexturedMaterialScalesAmbientAndDiffuse) {
    Material m;
    m.ka = Vec3(0.5f);
    m.kd = Vec3(1.0f);
    m.ks = Vec3(0.3f);
    CheckerTexture checker;
    checker.color_a = {1.0f, 0.5f, 0.25f};
    m.texture = checker;
    SurfacePoint<float> s;
    s.position = {0.5f, 0.5f, 0.5f};  // an even cell: colour_a
    const MaterialSample<float> sample = evaluate_material<float>(&m, 0, s);
    EXPECT_EQ(sample.ka, Vec3(0.5f, 0.25f, 0.125f));
    EXPECT_EQ(sample.kd, Vec3(1.0f, 0.5f, 0.25f));
    EXPECT_EQ(sample.ks, Vec3(0.3f));
}

/// Random materials (checkers, integer and other exponents), lights of every kind.
struct RandomWorld {
    std::vector<Material> materials;
    std::vector<Light> lights;

    explicit RandomWorld(Pcg32& rng) {
        const auto colour = [&] {
            return Vec3(rng.next_float(), rng.next_float(), rng.next_float());
        };
        const float exponents[] = {1.0f, 40.0f, 12.5f, 0.0f, 1024.0f};
        for (int i = 0; i < 5; ++i) {
            Material m;
            m.ka = colour() * 0.2f, m.kd = colour(), m.ks = i == 3 ? Vec3(0.0f) : colour();
            m.shininess = exponents[i];
            if (i % 2 == 0) {
                CheckerTexture c;
                c.size = 0.2f + rng.next_float();
                c.color_a = colour(), c.color_b = colour();
                m.texture = c;
            }
            materials.push_back(m);
        }
        lights = {PointLight{Vec3(1, 4, 2), Vec3(9.0f), true},
                  PointLight{Vec3(-3, 1, 0), Vec3(0.5f), false},
                  DirectionalLight{normalize(Vec3(0.3f, -1, 0.2f)), Vec3(0.7f)}};
    }
};

Vec3 random_unit(Pcg32& rng) {
    return normalize(
        Vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, rng.next_float() - 0.5f));
}

TEST(DirectLighting, LanesGiveTheOnePointBits) {
    Pcg32 rng(5, 2);
    const RandomWorld world(rng);
    const LightingEnvironment env{world.lights.data(), world.lights.size(), Vec3(0.2f)};
    for (int round = 0; round < 50; ++round) {
        SurfacePoint<float> points[k_lanes16];
        int32_t material[k_lanes16], visible_bits[k_lanes16];
        alignas(64) float lanes[4][3][k_lanes16];  // position, normal, geometric normal, to_eye
        for (int i = 0; i < k_lanes16; ++i) {
            SurfacePoint<float>& p = points[i];
            p.position = random_unit(rng) * (3.0f * rng.next_float());
            p.normal = random_unit(rng);
            p.geometric_normal = random_unit(rng);
            p.to_eye = random_unit(rng);
            material[i] = static_cast<int32_t>(rng.next_u32() % world.materials.size());
            visible_bits[i] = static_cast<int32_t>(rng.next_u32() % 8);
            const Vec3* fields[4] = {&p.position, &p.normal, &p.geometric_normal, &p.to_eye};
            for (int f = 0; f < 4; ++f)
                for (int a = 0; a < 3; ++a) lanes[f][a][i] = (*fields[f])[a];
        }
        SurfacePoint<Floats> pack;
        Vec3T<Floats>* fields[4] = {&pack.position, &pack.normal, &pack.geometric_normal,
                                    &pack.to_eye};
        for (int f = 0; f < 4; ++f)
            *fields[f] = {Floats::load(lanes[f][0]), Floats::load(lanes[f][1]),
                          Floats::load(lanes[f][2])};
        const Ints bits = Ints::load(visible_bits);
        const auto pack_visible = [&](size_t l, const auto&, const auto&, const Masks&) {
            return (bits & Ints(1 << l)) != Ints(0);
        };
        const MaterialSample<Floats> m =
            evaluate_material<Floats>(world.materials.data(), Ints::load(material), pack);
        const DirectLighting<Floats> got =
            direct_lighting<Floats>(env, pack, m, true, pack_visible);
        for (int i = 0; i < k_lanes16; ++i) {
            const auto visible = [&](size_t l, const LightSample&, const SurfacePoint<float>&,
                                     bool) { return ((visible_bits[i] >> l) & 1) != 0; };
            const MaterialSample<float> one =
                evaluate_material<float>(world.materials.data(), material[i], points[i]);
            const DirectLighting<float> want =
                direct_lighting<float>(env, points[i], one, true, visible);
            // std::pow's exponents and checkers (filtered per point) are the one-point code's.
            const Material& mat = world.materials[static_cast<size_t>(material[i])];
            EXPECT_EQ(m.scalar_only[i], one.exponent < 0 || mat.texture.has_value())
                << "lane " << i;
            EXPECT_EQ(got.tested[i], want.tested);
            if (m.scalar_only[i]) continue;  // std::pow's exponents: the one-point code's job
            for (int a = 0; a < 3; ++a)
                ASSERT_EQ(std::bit_cast<uint32_t>(got.colour[a][i]),
                          std::bit_cast<uint32_t>(want.colour[a]))
                    << "lane " << i << " channel " << a;
        }
    }
}

}  // namespace
}  // namespace hikari
