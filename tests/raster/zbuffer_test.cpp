#include "hikari/raster/zbuffer.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <algorithm>

#include "hikari/core/rng.h"
#include "hikari/integrators/whitted/whitted.h"
#include "hikari/raster/shade_visibility.h"
#include "hikari/raster/vertex_pipeline.h"
#include "raster_test_util.h"

namespace hikari {
namespace {

/// `count` random, interpenetrating triangles in [-1, 1]³ seen from z = 4 at 256 × 256.
std::string random_triangles_scene(int count, uint64_t seed) {
    Pcg32 rng(seed, 7);
    auto r = [&] { return 2 * rng.next_float() - 1; };
    std::string objects;
    for (int i = 0; i < count; ++i) {
        const float cx = r(), cy = r(), cz = r();
        objects += fmt::format(
            R"({}{{"type": "triangle", "vertices": [[{},{},{}],[{},{},{}],[{},{},{}]]}})",
            i ? "," : "", cx + r(), cy + r(), cz + r(), cx + r(), cy + r(), cz + r(), cx + r(),
            cy + r(), cz + r());
    }
    return R"({"camera": {"eye": [0, 0, 4], "look_at": [0, 0, 0], "fov_y": 50, "width": 256,
               "height": 256}, "objects": [)" +
           objects + "]}";
}

TEST(ZBuffer, NearerFragmentWins) {
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0, 0, 3], "look_at": [0, 0, 0], "width": 16, "height": 16},
      "objects": [
        {"type": "triangle", "vertices": [[-5, -5, -1], [5, -5, -1], [0, 5, -1]]},
        {"type": "triangle", "vertices": [[-5, -5, 0], [5, -5, 0], [0, 5, 0]]},
        {"type": "triangle", "vertices": [[-5, -5, -2], [5, -5, -2], [0, 5, -2]]}]})");
    const Framebuffer fb = render_zbuffer(scene, Film(scene.camera));
    EXPECT_EQ(fb.id[8 * 16 + 8], 2u);
    EXPECT_GT(fb.depth[8 * 16 + 8], 3.0f);
    EXPECT_LT(fb.depth[8 * 16 + 8], 3.1f);
}

TEST(ZBuffer, RandomInterpenetratingTrianglesMatchRayCaster) {
    for (uint64_t seed : {1u, 2u, 3u}) {
        const Scene scene = testing::raster_scene_from(random_triangles_scene(40, seed));
        EXPECT_GE(testing::id_agreement(render_whitted(scene, Film(scene.camera)),
                                        render_zbuffer(scene, Film(scene.camera))),
                  0.998)
            << "seed " << seed;
    }
}

TEST(ZBuffer, PiercingTrianglesAndCyclicBarsMatchRayCaster) {
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "fov_y": 50, "width": 256, "height": 256},
      "objects": [
        {"type": "triangle", "vertices": [[-1.5, -1, -1], [1.5, -1, 1], [0, 1.5, 0]]},
        {"type": "triangle", "vertices": [[-1.5, -1, 1], [1.5, -1, -1], [0, 1.2, -0.2]]},
        {"type": "triangle", "vertices": [[-2, -1.6, 0.3], [2, -1.4, -0.3], [2, -1.2, -0.3]]},
        {"type": "triangle", "vertices": [[1.6, -2, 0.3], [1.4, 2, -0.3], [1.2, 2, -0.3]]},
        {"type": "triangle", "vertices": [[2, 1.6, 0.3], [-2, 1.4, -0.3], [-2, 1.2, -0.3]]}]})");
    EXPECT_GE(testing::id_agreement(render_whitted(scene, Film(scene.camera)),
                                    render_zbuffer(scene, Film(scene.camera))),
              0.998);
}

TEST(ZBuffer, BunnyMatchesRayTracerWithoutVisibleShadows) {
    // A point light at the eye lights every visible point, so the ray tracer's shadows are never
    // seen and both pipelines evaluate the same shading model on the same triangles.
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [-0.17, 1.1, 3.5], "look_at": [-0.17, 1.0, 0], "fov_y": 35,
                 "width": 256, "height": 256},
      "background": [0.1, 0.1, 0.15], "ambient": [0.1, 0.1, 0.1],
      "materials": {"m": {"ka": [0.8, 0.7, 0.6], "kd": [0.8, 0.7, 0.6], "ks": [0.4, 0.4, 0.4],
                          "shininess": 30}},
      "lights": [{"type": "point", "position": [-0.17, 1.1, 3.5], "intensity": [12, 12, 12]}],
      "objects": [{"type": "mesh", "file": "scenes/models/stanford-bunny.obj", "material": "m",
                   "transform": [{"scale": 10}]}]})");
    const Framebuffer ray = render_whitted(scene, Film(scene.camera));
    const Framebuffer z = render_zbuffer(scene, Film(scene.camera));
    EXPECT_GE(testing::id_agreement(ray, z), 0.998);
    EXPECT_GE(testing::psnr(ray, z), 40.0);
}

TEST(ZBuffer, SphereMatchesRayTracer) {
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0, 0, 4], "look_at": [0, 0, 0], "fov_y": 45, "width": 256, "height": 256},
      "ambient": [0.1, 0.1, 0.1],
      "materials": {"m": {"ka": [1, 0.5, 0.3], "kd": [0.7, 0.4, 0.2], "ks": [0.5, 0.5, 0.5],
                          "shininess": 40}},
      "lights": [{"type": "directional", "direction": [0, 0, -1], "intensity": [1, 1, 1]}],
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})");
    const Framebuffer ray = render_whitted(scene, Film(scene.camera));
    const Framebuffer z = render_zbuffer(scene, Film(scene.camera));
    EXPECT_GE(testing::id_agreement(ray, z), 0.998);
    EXPECT_GE(testing::psnr(ray, z), 40.0);
}

TEST(ZBuffer, ImageDoesNotDependOnThreadCount) {
    const Scene scene = testing::raster_scene_from(random_triangles_scene(60, 9));
    Framebuffer one;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = render_zbuffer(scene, Film(scene.camera));
    }
    const Framebuffer many = render_zbuffer(scene, Film(scene.camera));
    EXPECT_EQ(one.id, many.id);
    EXPECT_EQ(one.film.linear().pixels, many.film.linear().pixels);
    EXPECT_EQ(one.depth, many.depth);
}

/// The bunny on its floor under a point light and a directional light, small.
Scene small_bunny() { return testing::scene_file("bunny.json", 160, 120); }

TEST(ZBuffer, TiledShadingMatchesTheVisibilityBufferPass) {
    // render_zbuffer shades each tile as soon as its Z-buffer is done, in lanes; drawing the
    // whole visibility buffer first and shading it after must give the same bits.
    const Scene scene = small_bunny();
    for (const ShadowMode mode : {ShadowMode::none, ShadowMode::map, ShadowMode::pcf}) {
        RasterSettings raster;
        raster.shadows = mode;
        raster.shadow_map_size = 256;
        const Framebuffer tiled = render_zbuffer(scene, Film(scene.camera), {}, raster);
        const ProjectedScene ps = project_scene(scene, raster, SphereGeometry::exact);
        const VisibilityBuffer vis =
            zbuffer_visibility(ps.triangles, scene.camera.width, scene.camera.height);
        const Framebuffer whole = shade_visibility(scene, ps, vis, Film(scene.camera), {}, raster);
        EXPECT_EQ(tiled.film.linear().pixels, whole.film.linear().pixels);
        EXPECT_EQ(tiled.id, whole.id);
        EXPECT_EQ(tiled.depth, whole.depth);
        EXPECT_EQ(tiled.normal, whole.normal);
    }
}

TEST(ZBuffer, ShadowedImageDoesNotDependOnThreadsOrSimdLevel) {
    const Scene scene = small_bunny();
    RasterSettings raster;
    raster.shadows = ShadowMode::map;
    raster.shadow_map_size = 256;
    Framebuffer reference;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        raster.simd = SimdLevel::portable;
        reference = render_zbuffer(scene, Film(scene.camera), {}, raster);
    }
    for (const SimdLevel level : supported_simd_levels()) {
        raster.simd = level;
        const Framebuffer fb = render_zbuffer(scene, Film(scene.camera), {}, raster);
        EXPECT_EQ(fb.film.linear().pixels, reference.film.linear().pixels)
            << simd_level_name(level);
        EXPECT_EQ(fb.id, reference.id) << simd_level_name(level);
    }
}

TEST(ZBuffer, AovBuffersOnlyWhenAsked) {
    const Scene scene = small_bunny();
    RenderSettings colour_only;
    colour_only.aov_buffers = false;
    const Framebuffer lean = render_zbuffer(scene, Film(scene.camera), colour_only);
    EXPECT_TRUE(lean.depth.empty());
    EXPECT_TRUE(lean.id.empty());
    EXPECT_TRUE(lean.normal.empty());
    const Framebuffer full = render_zbuffer(scene, Film(scene.camera));
    ASSERT_EQ(full.id.size(), static_cast<size_t>(160 * 120));
    EXPECT_EQ(lean.film.linear().pixels, full.film.linear().pixels);
    EXPECT_GT(std::count_if(full.id.begin(), full.id.end(), [](uint32_t id) { return id != 0; }),
              1000);
}

TEST(ZBuffer, StatsCountTheKernelsFragments) {
    // --stats counts fragments in the SIMD kernel: at least one per covered pixel, and the
    // picture is the one drawn without stats.
    const Scene scene = small_bunny();
    RenderStats stats;
    RenderSettings settings;
    settings.stats = &stats;
    const Framebuffer counted = render_zbuffer(scene, Film(scene.camera), settings);
    const Framebuffer plain = render_zbuffer(scene, Film(scene.camera));
    EXPECT_EQ(counted.film.linear().pixels, plain.film.linear().pixels);
    const uint64_t covered = stats.raster_covered_pixels.load();
    EXPECT_EQ(covered, static_cast<uint64_t>(std::count_if(plain.id.begin(), plain.id.end(),
                                                           [](uint32_t id) { return id != 0; })));
    EXPECT_GE(stats.raster_fragments.load(), covered);
}

}  // namespace
}  // namespace hikari
