// The camera-ray front end of Whitted ray tracing: a block's rays and nearest hits must be
// exactly those of camera_ray + SceneIntersector::closest, at every SIMD level, and renders
// through it bit-identical to ray-at-a-time renders.
#include "hikari/integrators/whitted/primary_hits.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <bit>
#include <cstring>

#include "../../bvh/test_meshes.h"
#include "../../io/scene_test_util.h"
#include "../../support/same_bits.h"
#include "hikari/core/rng.h"
#include "hikari/geometry/ray_offset.h"
#include "hikari/integrators/whitted/whitted.h"
#include "hikari/io/scene/scene_json.h"
#include "recursive_whitted.h"

namespace hikari {
namespace {

using testing::parse;
using testing::same_bits;

std::vector<SimdLevel> levels() {
    std::vector<SimdLevel> out;
    for (SimdLevel l : {SimdLevel::portable, SimdLevel::avx2, SimdLevel::avx512})
        if (simd_level_supported(l)) out.push_back(l);
    return out;
}

/// Every pixel of the scene's camera traced by blocks (clipped at the image's edges) against
/// the scalar reference, at every SIMD level.
void expect_blocks_match_closest(const Scene& scene) {
    const SceneIntersector intersector(scene);
    const CameraFrame frame = make_camera_frame(scene.camera);
    const int width = scene.camera.width, height = scene.camera.height;
    int hits = 0, shadowed = 0;
    for (SimdLevel level : levels()) {
        SCOPED_TRACE(simd_level_name(level));
        const PrimaryHitTracer tracer(intersector, scene, frame, level);
        PrimaryBlock block;
        for (int y0 = 0; y0 < height; y0 += k_primary_block)
            for (int x0 = 0; x0 < width; x0 += k_primary_block) {
                const int w = std::min(k_primary_block, width - x0);
                const int h = std::min(k_primary_block, height - y0);
                tracer.trace(x0, y0, w, h, block);
                for (int y = 0; y < h; ++y)
                    for (int x = 0; x < w; ++x) {
                        const int k = y * k_primary_block + x;
                        const Ray ray = camera_ray(frame, static_cast<float>(x0 + x) + 0.5f,
                                                   static_cast<float>(y0 + y) + 0.5f);
                        ASSERT_TRUE(same_bits(ray.origin, block.ray(k).origin));
                        ASSERT_TRUE(same_bits(ray.direction, block.ray(k).direction))
                            << "pixel " << x0 + x << ", " << y0 + y;
                        SurfaceHit expected;
                        const bool found = intersector.closest(ray, {0.0f, k_infinity}, expected);
                        ASSERT_EQ(found, block.found(k) != 0)
                            << "pixel " << x0 + x << ", " << y0 + y;
                        if (!found) continue;
                        ++hits;
                        const SurfaceHit got = block.hit(k);
                        ASSERT_TRUE(same_bits(expected.t, got.t)) << expected.t << " " << got.t;
                        ASSERT_TRUE(same_bits(expected.position, got.position));
                        ASSERT_TRUE(same_bits(expected.geometric_normal, got.geometric_normal));
                        ASSERT_TRUE(same_bits(expected.shading_normal, got.shading_normal));
                        ASSERT_EQ(expected.material, got.material);
                        ASSERT_EQ(expected.id, got.id);
                        // Which primitive, and where on a triangle: what texture coordinates
                        // are computed from.
                        ASSERT_EQ(expected.kind, got.kind);
                        ASSERT_EQ(expected.index, got.index);
                        ASSERT_TRUE(same_bits(expected.bary_u, got.bary_u));
                        ASSERT_TRUE(same_bits(expected.bary_v, got.bary_v));
                        // The shadow rays shade_local would trace from this hit.
                        ASSERT_TRUE(block.shadows_known);
                        const Vec3 ng = dot(got.geometric_normal, ray.direction) < 0.0f
                                            ? got.geometric_normal
                                            : -got.geometric_normal;
                        const Vec3 origin = offset_ray_origin(got.position, ng);
                        for (size_t l = 0; l < scene.lights.size(); ++l) {
                            const LightSample ls = sample_light(scene.lights[l], got.position);
                            const bool blocked =
                                intersector.occluded({origin, ls.to_light}, {0.0f, ls.distance});
                            ASSERT_EQ(!blocked, (block.lit(k) >> l & 1u) != 0) << "light " << l;
                            shadowed += blocked ? 1 : 0;
                        }
                    }
            }
    }
    EXPECT_GT(hits, 0);
    if (!scene.lights.empty()) EXPECT_GT(shadowed, 0);
}

/// A random scene: spheres (some overlapping, one duplicated for exact ties), planes (one twice),
/// a triangle soup, and a camera placed at random (sometimes inside a sphere).
Scene random_scene_with_ties(uint64_t seed) {
    Pcg32 rng(seed, 7);
    Scene scene;
    scene.materials.resize(3);
    PrimitiveId id = 0;
    for (int i = 0; i < 6; ++i) {
        Sphere s;
        s.center = testing::random_point(rng, 3.0f);
        s.radius = 0.2f + 1.5f * rng.next_float();
        s.material = static_cast<uint32_t>(i % 3);
        s.id = id++;
        s.casts_shadow = i != 3;
        scene.spheres.push_back(s);
    }
    Sphere twin = scene.spheres[2];
    twin.id = id++;
    scene.spheres.push_back(twin);  // same t as sphere 2: the first must win
    for (int i = 0; i < 2; ++i) {
        Plane p;
        p.point = testing::random_point(rng, 4.0f);
        p.normal = testing::random_direction(rng);
        p.material = 1;
        p.id = id++;
        scene.planes.push_back(p);
    }
    Plane twin_plane = scene.planes[0];
    twin_plane.id = id++;
    scene.planes.push_back(twin_plane);
    testing::set_scene_triangles(scene.triangles, testing::random_soup(200, 0.8f, seed), id,
                                 [](size_t) { return uint32_t{2}; });
    scene.primitive_count = id;
    scene.lights.emplace_back(PointLight{testing::random_point(rng, 6.0f), Vec3(1.0f), true});
    scene.lights.emplace_back(DirectionalLight{testing::random_direction(rng), Vec3(1.0f)});
    Camera& cam = scene.camera;
    cam.eye = (seed % 3 == 0) ? scene.spheres[0].center  // inside a sphere
                              : testing::random_point(rng, 8.0f);
    cam.look_at = testing::random_point(rng, 1.0f);
    cam.fov_y_degrees = 20.0f + 80.0f * rng.next_float();
    cam.width = 37;  // clipped blocks on both axes
    cam.height = 21;
    return scene;
}

TEST(PrimaryHits, RandomScenesMatchClosest) {
    for (uint64_t seed = 1; seed <= 12; ++seed) {
        SCOPED_TRACE(seed);
        expect_blocks_match_closest(random_scene_with_ties(seed));
    }
}

TEST(PrimaryHits, ManySpheresThroughTheirBvhMatchClosest) {
    // Past the lanes' limit the spheres are found one ray at a time through their BVH; the
    // answers (hits and shadows) must stay those of SceneIntersector::closest and occluded.
    for (uint64_t seed = 1; seed <= 3; ++seed) {
        SCOPED_TRACE(seed);
        Scene scene = random_scene_with_ties(seed);
        Pcg32 rng(seed, 11);
        for (int i = 0; i < 300; ++i) {
            Sphere s;
            s.center = testing::random_point(rng, 3.0f);
            s.radius = 0.05f + 0.3f * rng.next_float();
            s.material = static_cast<uint32_t>(i % 3);
            s.id = scene.primitive_count++;
            s.casts_shadow = i % 5 != 0;
            scene.spheres.push_back(s);
        }
        expect_blocks_match_closest(scene);
    }
}

TEST(PrimaryHits, NoTrianglesMatchClosest) {
    Scene scene = random_scene_with_ties(5);
    scene.triangles = TriangleSet{};
    expect_blocks_match_closest(scene);
}

TEST(PrimaryHits, OnlyTrianglesMatchClosest) {
    Scene scene = random_scene_with_ties(4);
    scene.spheres.clear();
    scene.planes.clear();
    expect_blocks_match_closest(scene);
}

TEST(PrimaryHits, CameraOnASphereMatchesClosest) {
    // The eye exactly on the surface: q = 0 for rays along the tangent plane.
    Scene scene = random_scene_with_ties(2);
    scene.camera.eye = scene.spheres[1].center + Vec3(scene.spheres[1].radius, 0.0f, 0.0f);
    expect_blocks_match_closest(scene);
}

std::string b3_scene_json(int width, int height) {
    std::vector<std::string> warnings;
    std::string json = R"({
      "camera": {"eye": [0, 2, 7], "look_at": [0, 1, 0], "up": [0, 1, 0], "fov_y": 45,
                 "width": )" +
                       std::to_string(width) + R"(, "height": )" + std::to_string(height) + R"(},
      "background": [0.8, 0.9, 1.0],
      "sky": {"type": "gradient", "horizon": [0.8, 0.9, 1.0], "zenith": [0.2, 0.4, 0.9]},
      "ambient": [1, 1, 1],
      "materials": {
        "checker": {"ka": 0.1, "kd": 0.8, "texture": {"type": "checker", "size": 1,
                    "color_a": [0.1, 0.1, 0.1], "color_b": [0.9, 0.9, 0.9], "offset": [0, 0.5, 0]}},
        "mirror": {"reflectivity": 0.9},
        "glass": {"ks": 0.8, "shininess": 200, "reflectivity": 0.1, "transparency": 1, "ior": 1.5},
        "red": {"ka": [0.08, 0.015, 0.015], "kd": [0.56, 0.105, 0.105], "ks": 0.6, "shininess": 40}
      },
      "lights": [{"type": "point", "position": [-5, 8, 6], "intensity": [1, 1, 1], "falloff": "none"}],
      "objects": [
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "checker"},
        {"type": "sphere", "center": [-2.2, 1, -1], "radius": 1, "material": "mirror"},
        {"type": "sphere", "center": [0, 1, 1], "radius": 1, "material": "glass", "casts_shadow": false},
        {"type": "sphere", "center": [2.2, 1, -1], "radius": 1, "material": "red"}
      ]})";
    return json;
}

void expect_same_framebuffer(const Framebuffer& a, const Framebuffer& b) {
    ASSERT_EQ(a.film.linear().pixels.size(), b.film.linear().pixels.size());
    for (size_t i = 0; i < a.film.linear().pixels.size(); ++i)
        ASSERT_TRUE(same_bits(a.film.linear().pixels[i], b.film.linear().pixels[i]))
            << "pixel " << i;
    ASSERT_EQ(a.depth.size(), b.depth.size());
    for (size_t i = 0; i < a.depth.size(); ++i) {
        ASSERT_TRUE(same_bits(a.depth[i], b.depth[i])) << "pixel " << i;
        ASSERT_EQ(a.id[i], b.id[i]);
        ASSERT_TRUE(same_bits(a.normal[i], b.normal[i]));
    }
}

TEST(PrimaryHits, WhittedRenderEqualsTheRecursiveOracle) {
    Scene scene = parse(b3_scene_json(203, 117));
    // The checker off: the product box-filters it over each ray's cone, which the recursive
    // oracle does not trace (the filter has tests of its own, the scene's render a pin).
    for (Material& m : scene.materials) m.texture.reset();
    expect_same_framebuffer(render_whitted(scene, Film(scene.camera)),
                            testing::render_whitted_recursive(scene));
}

TEST(PrimaryHits, MeshRenderEqualsTheRecursiveOracle) {
    std::vector<std::string> warnings;
    Scene scene = load_scene_file(std::string(HIKARI_SOURCE_DIR) + "/scenes/teapot.json", warnings);
    scene.camera.width = 150;
    scene.camera.height = 101;
    expect_same_framebuffer(render_whitted(scene, Film(scene.camera)),
                            testing::render_whitted_recursive(scene));
}

TEST(PrimaryHits, SameImageForAnyThreadCount) {
    const Scene scene = parse(b3_scene_json(160, 90));
    Framebuffer one, two;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = render_whitted(scene, Film(scene.camera));
    }
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        two = render_whitted(scene, Film(scene.camera));
    }
    expect_same_framebuffer(one, two);
}

}  // namespace
}  // namespace hikari
