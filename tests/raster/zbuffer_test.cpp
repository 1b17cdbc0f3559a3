#include "hikari/raster/zbuffer.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "hikari/core/rng.h"
#include "hikari/integrators/whitted/whitted.h"
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

}  // namespace
}  // namespace hikari
