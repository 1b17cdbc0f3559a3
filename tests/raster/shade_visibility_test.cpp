#include "hikari/raster/shade_visibility.h"

#include <gtest/gtest.h>

#include "hikari/integrators/whitted/whitted.h"
#include "hikari/raster/zbuffer.h"
#include "raster_test_util.h"

namespace hikari {
namespace {

TEST(ShadeVisibility, PerspectiveBarycentricsRecoverTheWorldPoint) {
    const Mat4 clip_from_world =
        perspective(50, 1.5f, 0.1f, 100) * look_at({1, 2, 3}, {0, 0, 0}, {0, 1, 0});
    const Vec3 p[3] = {{-1, 0, 0}, {2, 0.5f, -4}, {0, 1.5f, 1}};
    const float l[3] = {0.2f, 0.5f, 0.3f};
    const Vec3 q = l[0] * p[0] + l[1] * p[1] + l[2] * p[2];
    const Vec4 cq = clip_from_world * Vec4(q, 1);
    std::array<float, 3> b;
    ASSERT_TRUE(
        perspective_barycentrics(clip_from_world * Vec4(p[0], 1), clip_from_world * Vec4(p[1], 1),
                                 clip_from_world * Vec4(p[2], 1), cq.x / cq.w, cq.y / cq.w, b));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(b[i], l[i], 1e-5f);
}

TEST(ShadeVisibility, ReceedingQuadInterpolatesPerspectiveCorrectly) {
    // A long floor quad seen at a grazing angle: screen-linear interpolation would put the
    // pixel's surface point (and so its depth) far off; perspective-correct interpolation gives
    // the ray tracer's eye distances.
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0, 1, 0], "look_at": [0, 0.8, -4], "fov_y": 60, "width": 96, "height": 64},
      "ambient": [1, 1, 1], "materials": {"m": {"ka": [1, 1, 1]}},
      "objects": [
        {"type": "triangle", "vertices": [[-2, 0, -1], [2, 0, -1], [2, 0, -60]], "material": "m"},
        {"type": "triangle", "vertices": [[-2, 0, -1], [2, 0, -60], [-2, 0, -60]], "material": "m"}]})");
    const Framebuffer ray = render_whitted(scene, Film(scene.camera));
    const Framebuffer z = render_zbuffer(scene, Film(scene.camera));
    int compared = 0;
    for (size_t i = 0; i < ray.depth.size(); ++i)
        if (ray.id[i] != 0 && z.id[i] != 0) {
            EXPECT_NEAR(z.depth[i], ray.depth[i], 1e-4f * ray.depth[i]);
            ++compared;
        }
    EXPECT_GT(compared, 1000);
}

TEST(ShadeVisibility, InterpolationModesAgreeOnAFlatTriangle) {
    // One flat triangle under a directional light, no highlight: flat, Gouraud and Phong shading
    // all give the same Lambert colour.
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0, 0, 3], "look_at": [0, 0, 0], "width": 32, "height": 32},
      "ambient": [0.1, 0.1, 0.1], "materials": {"m": {"ka": [1, 1, 1], "kd": [0.5, 0.6, 0.7]}},
      "lights": [{"type": "directional", "direction": [0.3, -0.2, -1], "intensity": [1, 1, 1]}],
      "objects": [{"type": "triangle", "vertices": [[-1, -1, 0], [1, -1, 0], [0, 1, 0]],
                   "material": "m"}]})");
    RasterSettings s;
    const Framebuffer phong = render_zbuffer(scene, Film(scene.camera), {}, s);
    s.interp = Interpolation::gouraud;
    const Framebuffer gouraud = render_zbuffer(scene, Film(scene.camera), {}, s);
    s.interp = Interpolation::flat;
    const Framebuffer flat = render_zbuffer(scene, Film(scene.camera), {}, s);
    for (size_t i = 0; i < phong.film.linear().pixels.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(gouraud.film.linear().pixels[i][k], phong.film.linear().pixels[i][k],
                        1e-5f);
            EXPECT_NEAR(flat.film.linear().pixels[i][k], phong.film.linear().pixels[i][k], 1e-5f);
        }
}

}  // namespace
}  // namespace hikari
