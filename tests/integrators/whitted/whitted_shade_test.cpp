// The Whitted shading lanes: every SIMD level gives the same lanes, and renders shaded in lanes
// level by level are bit-identical to the recursive ray-at-a-time tracer, on scenes that use
// every material feature (textures, mirrors, glass with total internal reflection, integer and
// non-integer Phong exponents) under every kind of light, with one or several samples per pixel.
#include "hikari/integrators/whitted/whitted_shade.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <memory>

#include "../../bvh/test_meshes.h"
#include "../../support/same_bits.h"
#include "hikari/core/rng.h"
#include "hikari/core/srgb8_encoder.h"
#include "hikari/integrators/whitted/whitted.h"
#include "recursive_whitted.h"

namespace hikari {
namespace {

using testing::same_bits;

Vec3 random_colour(Pcg32& rng) { return {rng.next_float(), rng.next_float(), rng.next_float()}; }

/// Materials that between them use every parameter the lanes read.
std::vector<Material> random_materials(Pcg32& rng) {
    std::vector<Material> out;
    for (int i = 0; i < 7; ++i) {
        Material m;
        m.ka = random_colour(rng) * 0.2f;
        m.kd = random_colour(rng);
        m.ks = random_colour(rng);
        // Integer exponents (the lanes' squaring), a non-integer one and one beyond 1024 (both
        // left to the scalar code).
        const float exponents[] = {1.0f, 40.0f, 200.0f, 12.5f, 2000.0f, 0.0f, 1024.0f};
        m.shininess = exponents[i];
        m.reflectivity = i % 3 == 1 ? 0.5f + 0.4f * rng.next_float() : 0.0f;
        if (i == 2 || i == 5) {
            m.transparency = 0.9f;
            m.ior = i == 2 ? 1.5f : 0.8f;  // glass, and a bubble (less dense inside)
        }
        if (i % 2 == 0) {
            CheckerTexture checker;
            checker.size = 0.3f + rng.next_float();
            checker.color_a = random_colour(rng);
            checker.color_b = random_colour(rng);
            checker.offset = testing::random_point(rng, 1.0f);
            m.texture = checker;
        }
        out.push_back(m);
    }
    return out;
}

std::vector<Light> random_lights(Pcg32& rng) {
    return {PointLight{testing::random_point(rng, 6.0f), Vec3(20.0f), true},
            PointLight{testing::random_point(rng, 6.0f), Vec3(0.5f), false},
            DirectionalLight{testing::random_direction(rng), Vec3(0.7f)}};
}

/// Random hits with random normals and materials in every lane, some lanes inactive.
void fill_random_lanes(Pcg32& rng, uint32_t materials, uint32_t lights, detail::BlockLanes& lanes) {
    for (int i = 0; i < detail::k_shade_lanes; ++i) {
        const Vec3 d = testing::random_direction(rng), p = testing::random_point(rng, 5.0f);
        const Vec3 g = testing::random_direction(rng);
        const Vec3 s = normalize(g + 0.3f * testing::random_direction(rng));
        detail::LaneChunk& lane = lanes.chunk(i);
        const int j = detail::lane_in_chunk(i);
        for (int a = 0; a < 3; ++a) {
            lane.direction[a][j] = d[a];
            lane.position[a][j] = p[a];
            lane.geometric_normal[a][j] = g[a];
            lane.shading_normal[a][j] = s[a];
        }
        lane.material[j] = static_cast<int32_t>(rng.next_u32() % materials);
        lane.lit[j] = static_cast<int32_t>(rng.next_u32() % (1u << lights));
        lane.active[j] = rng.next_float() < 0.9f ? 1 : 0;
    }
}

TEST(WhittedShade, EveryLevelShadesAlike) {
    Pcg32 rng(11, 3);
    Scene scene;
    scene.materials = random_materials(rng);
    scene.lights = random_lights(rng);
    scene.ambient = Vec3(0.3f, 0.4f, 0.5f);
    const WhittedScene view(scene);
    const LaneShader reference(view, SimdLevel::portable);
    auto input = std::make_unique<detail::BlockLanes>();
    auto expected = std::make_unique<detail::BlockLanes>();
    auto got = std::make_unique<detail::BlockLanes>();
    for (int round = 0; round < 8; ++round) {
        fill_random_lanes(rng, static_cast<uint32_t>(scene.materials.size()),
                          static_cast<uint32_t>(scene.lights.size()), *input);
        // Full blocks and partial ones (the kernel then runs only the chunks that hold lanes).
        const int count = round % 2 == 0
                              ? detail::k_shade_lanes
                              : 1 + static_cast<int>(rng.next_u32() % detail::k_shade_lanes);
        for (int i = count; i < lanes_for(count); ++i) {
            const int j = detail::lane_in_chunk(i);
            input->chunk(i).active[j] = 0, input->chunk(i).material[j] = 0;
        }
        std::memcpy(expected.get(), input.get(), sizeof(detail::BlockLanes));
        reference.shade(*expected, count, true);
        for (SimdLevel level : {SimdLevel::avx2, SimdLevel::avx512}) {
            if (!simd_level_supported(level)) continue;
            SCOPED_TRACE(simd_level_name(level));
            std::memcpy(got.get(), input.get(), sizeof(detail::BlockLanes));
            LaneShader(view, level).shade(*got, count, true);
            for (int i = 0; i < count; ++i) {
                const int j = detail::lane_in_chunk(i);
                const detail::LaneChunk& want = expected->chunk(i);
                const detail::LaneChunk& have = got->chunk(i);
                if (!input->chunk(i).active[j]) continue;
                ASSERT_EQ(want.shadow_rays[j], have.shadow_rays[j]);
                ASSERT_EQ(want.scalar_only[j], have.scalar_only[j]);
                for (int a = 0; a < 3; ++a) {
                    ASSERT_TRUE(same_bits(want.colour[a][j], have.colour[a][j])) << i;
                    // A secondary ray is only read where its weight is positive.
                    ASSERT_TRUE(
                        same_bits(want.mirror_direction[a][j], have.mirror_direction[a][j]) ||
                        want.mirror_weight[j] == 0.0f);
                    ASSERT_TRUE(same_bits(want.mirror_origin[a][j], have.mirror_origin[a][j]) ||
                                want.mirror_weight[j] == 0.0f);
                    ASSERT_TRUE(
                        same_bits(want.refract_direction[a][j], have.refract_direction[a][j]) ||
                        want.refract_weight[j] == 0.0f);
                    ASSERT_TRUE(same_bits(want.refract_origin[a][j], have.refract_origin[a][j]) ||
                                want.refract_weight[j] == 0.0f);
                }
                ASSERT_TRUE(same_bits(want.mirror_weight[j], have.mirror_weight[j]));
                ASSERT_TRUE(same_bits(want.refract_weight[j], have.refract_weight[j]));
                ASSERT_EQ(want.children[j], have.children[j]);
            }
        }
    }
}

/// Spheres (some overlapping, some not casting shadows), a ground plane and a smooth-shaded
/// triangle soup, all materials of random_materials, lit by random_lights. `textured` false:
/// the checkers taken off (the product box-filters them over each ray's cone, which the
/// recursive oracle does not trace; the checker's filter has tests of its own).
Scene random_lit_scene(uint64_t seed, bool textured = true) {
    Pcg32 rng(seed, 5);
    Scene scene;
    scene.materials = random_materials(rng);
    if (!textured)
        for (Material& m : scene.materials) m.texture.reset();
    scene.lights = random_lights(rng);
    scene.ambient = Vec3(0.2f);
    scene.background = Vec3(0.1f, 0.2f, 0.3f);
    if (seed % 2 == 0) scene.sky = Sky{true, Vec3(0.8f, 0.9f, 1.0f), Vec3(0.2f, 0.4f, 0.9f)};
    const auto materials = static_cast<uint32_t>(scene.materials.size());
    PrimitiveId id = 0;
    for (int i = 0; i < 8; ++i) {
        Sphere s;
        s.center = testing::random_point(rng, 3.0f);
        s.radius = 0.3f + rng.next_float();
        s.material = static_cast<uint32_t>(i) % materials;
        s.id = id++;
        s.casts_shadow = i != 2;
        scene.spheres.push_back(s);
    }
    Plane ground;
    ground.point = Vec3(0.0f, -3.0f, 0.0f);
    ground.normal = Vec3(0.0f, 1.0f, 0.0f);
    ground.material = 0;
    ground.id = id++;
    scene.planes.push_back(ground);
    testing::set_scene_triangles(scene.triangles, testing::random_soup(60, 0.8f, seed), id,
                                 [&](size_t i) { return static_cast<uint32_t>(i) % materials; });
    scene.primitive_count = id;
    Camera& cam = scene.camera;
    cam.eye = seed % 3 == 0 ? scene.spheres[0].center : testing::random_point(rng, 9.0f);
    cam.look_at = testing::random_point(rng, 1.0f);
    cam.fov_y_degrees = 30.0f + 60.0f * rng.next_float();
    cam.width = 45;  // clipped blocks on both axes
    cam.height = 29;
    return scene;
}

void expect_same_colours(const Framebuffer& a, const Framebuffer& b) {
    const Image& ca = a.film.linear();
    const Image& cb = b.film.linear();
    ASSERT_EQ(ca.pixels.size(), cb.pixels.size());
    for (size_t i = 0; i < ca.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            ASSERT_TRUE(same_bits(ca.pixels[i][c], cb.pixels[i][c]))
                << "pixel " << i << ": " << ca.pixels[i][c] << " vs " << cb.pixels[i][c];
    ASSERT_EQ(a.depth.size(), b.depth.size());
    for (size_t i = 0; i < a.depth.size(); ++i) {
        ASSERT_TRUE(same_bits(a.depth[i], b.depth[i]));
        ASSERT_EQ(a.id[i], b.id[i]);
    }
}

TEST(WhittedShade, RandomScenesRenderAsTheRecursiveOracle) {
    for (uint64_t seed = 1; seed <= 6; ++seed)
        for (int depth : {1, 2, 6})
            for (int spp : {1, 4}) {
                SCOPED_TRACE(::testing::Message()
                             << "seed " << seed << " depth " << depth << " spp " << spp);
                const Scene scene = random_lit_scene(seed, false);
                WhittedSettings whitted;
                whitted.max_depth = depth;
                whitted.samples_per_pixel = spp;
                expect_same_colours(render_whitted(scene, Film(scene.camera), {}, whitted),
                                    testing::render_whitted_recursive(scene, whitted));
            }
}

TEST(WhittedShade, ManyLightsAreShadedByTheOneRayCode) {
    // As many lights as a block's lit bits hold (the lanes shade, bit 31 included), and one more:
    // every hit then falls back to the one-ray code, which casts its own shadow rays. Neither
    // may change the image.
    for (const size_t lights : {k_max_block_lights, k_max_block_lights + 1}) {
        SCOPED_TRACE(::testing::Message() << lights << " lights");
        Scene scene = random_lit_scene(4, false);
        Pcg32 rng(7, 9);
        while (scene.lights.size() < lights)
            scene.lights.push_back(PointLight{testing::random_point(rng, 6.0f), Vec3(0.4f), true});
        expect_same_colours(render_whitted(scene, Film(scene.camera)),
                            testing::render_whitted_recursive(scene));
    }
}

TEST(WhittedShade, Srgb8OutputIsTheEncodedLinearRender) {
    // Lanes (one sample) and the ray-at-a-time path (several): each pixel's colour is encoded as
    // the PNG writer encodes the float framebuffer.
    for (int spp : {1, 4}) {
        SCOPED_TRACE(::testing::Message() << "spp " << spp);
        const Scene scene = random_lit_scene(3);
        RenderSettings colour_only;
        colour_only.aov_buffers = false;
        WhittedSettings whitted;
        whitted.samples_per_pixel = spp;
        const Framebuffer a = render_whitted(scene, Film(scene.camera), colour_only, whitted);
        const Framebuffer b =
            render_whitted(scene, Film(scene.camera, FilmFormat::srgb8), colour_only, whitted);
        ASSERT_TRUE(a.film.srgb8().bytes.empty());
        ASSERT_TRUE(b.film.linear().pixels.empty());
        ASSERT_EQ(b.width(), a.width());
        ASSERT_EQ(b.height(), a.height());
        EXPECT_EQ(encode_srgb8(a.film.linear()).bytes, b.film.srgb8().bytes);
    }
}

}  // namespace
}  // namespace hikari
