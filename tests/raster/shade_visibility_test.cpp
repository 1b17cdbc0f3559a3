#include "hikari/raster/shade_visibility.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "hikari/integrators/whitted/whitted.h"
#include "hikari/raster/depth_sort.h"
#include "hikari/raster/scanline.h"
#include "hikari/raster/zbuffer.h"
#include "hikari/shading/textures/image_texture.h"
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

/// The uv of the floor y = 0 under the mapping (u, v) = (x, −z) / 2 where the camera ray through
/// pixel point (px, py) meets it.
Vec2 floor_uv_seen(const CameraFrame& frame, float px, float py) {
    const Ray r = camera_ray(frame, px, py);
    const Vec3 p = r.at(-r.origin.y / r.direction.y);
    return {p.x / 2, -p.z / 2};
}

TEST(ShadeVisibility, PerspectiveUvAndItsDerivativesOnAFloor) {
    // A floor quad whose corners carry the planar mapping (x, −z) / 2, seen obliquely: every
    // pixel's interpolated uv is the mapping at the point its camera ray meets (perspective-
    // correct), and the derivatives are those of that point moving across the pixel grid.
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0, 1, 0], "look_at": [0.3, 0.6, -4], "fov_y": 60, "width": 96, "height": 64},
      "objects": [
        {"type": "triangle", "vertices": [[-4, 0, -1], [4, 0, -1], [4, 0, -30]],
         "uvs": [[-2, 0.5], [2, 0.5], [2, 15]]},
        {"type": "triangle", "vertices": [[-4, 0, -1], [4, 0, -30], [-4, 0, -30]],
         "uvs": [[-2, 0.5], [2, 15], [-2, 15]]}]})");
    const ProjectedScene ps = project_scene(scene, {});
    const CameraFrame frame = make_camera_frame(scene.camera);
    const TriangleSet& tris = ps.scene.triangles;
    int checked = 0;
    for (int y = 40; y < 64; y += 3)
        for (int x = 2; x < 96; x += 5) {
            const float px = x + 0.5f, py = y + 0.5f;
            const Vec2 want = floor_uv_seen(frame, px, py);
            // The mapping is affine over the floor's plane: either triangle interpolates it.
            const auto& i = tris.indices[0];
            const PixelUv got = perspective_uv(
                {ps.clip_positions[i[0]], ps.clip_positions[i[1]], ps.clip_positions[i[2]]},
                {tris.uvs[i[0]], tris.uvs[i[1]], tris.uvs[i[2]]}, 2.0 * px / 96 - 1,
                1 - 2.0 * py / 64, 96, 64);
            EXPECT_NEAR(got.uv.x, want.x, 1e-3f * (1 + std::abs(want.x)));
            EXPECT_NEAR(got.uv.y, want.y, 1e-3f * (1 + std::abs(want.y)));
            // Central differences of the ray-traced mapping, a hundredth of a pixel apart.
            const float h = 0.01f;
            const Vec2 xp = floor_uv_seen(frame, px + h, py), xm = floor_uv_seen(frame, px - h, py);
            const Vec2 yp = floor_uv_seen(frame, px, py + h), ym = floor_uv_seen(frame, px, py - h);
            const float tol = 0.02f * std::hypot((yp.x - ym.x) / (2 * h), (yp.y - ym.y) / (2 * h));
            EXPECT_NEAR(got.du_dx, (xp.x - xm.x) / (2 * h), tol);
            EXPECT_NEAR(got.dv_dx, (xp.y - xm.y) / (2 * h), tol);
            EXPECT_NEAR(got.du_dy, (yp.x - ym.x) / (2 * h), tol);
            EXPECT_NEAR(got.dv_dy, (yp.y - ym.y) / (2 * h), tol);
            ++checked;
        }
    EXPECT_GT(checked, 100);
}

TEST(ShadeVisibility, PerspectiveUvOfAFacingQuadIsItsPixelSize) {
    // A quad 4 units in front of a 90° camera, 200 pixels high: one pixel is 8/200 = 0.04 world
    // units there, so with one texture repeat per 2 units, 0.02 in u per pixel along x and
    // −0.02 in v per pixel down the image.
    const Mat4 clip_from_world =
        perspective(90, 1.0f, 0.1f, 100) * look_at({0, 0, 0}, {0, 0, -1}, {0, 1, 0});
    const std::array<Vec4, 3> clip{clip_from_world * Vec4({-3, -3, -4}, 1),
                                   clip_from_world * Vec4({3, -3, -4}, 1),
                                   clip_from_world * Vec4({-3, 3, -4}, 1)};
    const PixelUv got = perspective_uv(
        clip, {Vec2{-1.5f, -1.5f}, Vec2{1.5f, -1.5f}, Vec2{-1.5f, 1.5f}}, 0.1, -0.2, 200, 200);
    EXPECT_NEAR(got.uv.x, 0.1f * 4 / 2, 1e-5f);
    EXPECT_NEAR(got.uv.y, -0.2f * 4 / 2, 1e-5f);
    EXPECT_NEAR(got.du_dx, 0.02f, 1e-6f);
    EXPECT_NEAR(got.dv_dx, 0.0f, 1e-6f);
    EXPECT_NEAR(got.du_dy, 0.0f, 1e-6f);
    EXPECT_NEAR(got.dv_dy, -0.02f, 1e-6f);
}

TEST(ShadeVisibility, TexturedQuadMatchesAnIndependentBilinearRender) {
    // scenes/models/checker.png magnified on a quad facing the camera: every method's pixel is
    // the bilinear sample of the full-size image at the uv computed here, independently, from
    // the camera ray's hit on the quad.
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0.1, -0.2, 2], "look_at": [0.1, -0.2, 0], "fov_y": 30, "width": 64, "height": 48},
      "ambient": 1,
      "materials": {"m": {"ka": 1, "texture": {"type": "image", "file": "scenes/models/checker.png"}}},
      "objects": [
        {"type": "triangle", "vertices": [[-1, -1, 0], [1, -1, 0], [1, 1, 0]],
         "uvs": [[0, 0], [0.25, 0], [0.25, 0.25]], "material": "m"},
        {"type": "triangle", "vertices": [[-1, -1, 0], [1, 1, 0], [-1, 1, 0]],
         "uvs": [[0, 0], [0.25, 0.25], [0, 0.25]], "material": "m"}]})");
    const auto& texture = std::get<ImageTexture>(*scene.materials[0].texture);
    const CameraFrame frame = make_camera_frame(scene.camera);
    Framebuffer reference(Film(scene.camera), 64, 48, false);
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x) {
            const Ray r = camera_ray(frame, x + 0.5f, y + 0.5f);
            const Vec3 p = r.at(-r.origin.z / r.direction.z);
            reference.set_color(static_cast<size_t>(y) * 64 + x,
                                sample_bilinear(texture.pyramid->levels[0], (p.x + 1) / 8,
                                                (p.y + 1) / 8, TextureWrap::repeat));
        }
    EXPECT_GT(testing::psnr(render_whitted(scene, Film(scene.camera)), reference), 35.0);
    EXPECT_GT(testing::psnr(render_zbuffer(scene, Film(scene.camera)), reference), 35.0);
    EXPECT_GT(testing::psnr(render_scanline(scene, Film(scene.camera)), reference), 35.0);
    EXPECT_GT(testing::psnr(render_depth_sort(scene, Film(scene.camera)), reference), 35.0);
}

TEST(ShadeVisibility, TexturedSpotAgreesWithTheRayTracer) {
    // scenes/spot.json: OBJ uvs, a 1024² texture minified; every raster method picks the same
    // texels and mip levels as the ray tracer's ray cones.
    const Scene scene = testing::scene_file("spot.json", 96, 96);
    const Framebuffer ray = render_whitted(scene, Film(scene.camera));
    EXPECT_GT(testing::psnr(render_zbuffer(scene, Film(scene.camera)), ray), 35.0);
    EXPECT_GT(testing::psnr(render_scanline(scene, Film(scene.camera)), ray), 35.0);
    EXPECT_GT(testing::psnr(render_depth_sort(scene, Film(scene.camera)), ray), 35.0);
}

TEST(ShadeVisibility, TexturedSphereAndPlaneAgreeWithTheRayTracer) {
    // The tessellated sphere and plane carry the ray tracer's analytic mappings: seen from
    // behind and above, the sphere shows its seam (u = 0 ≡ 1, facing −z) and its north pole.
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0.3, 2.2, -3], "look_at": [0, 0.4, 0], "fov_y": 40, "width": 96, "height": 96},
      "ambient": 1,
      "materials": {
        "globe": {"ka": 1, "texture": {"type": "image", "file": "scenes/models/spot_texture.png"}},
        "floor": {"ka": 1, "texture": {"type": "image", "file": "scenes/models/checker.png"}}},
      "objects": [
        {"type": "sphere", "center": [0, 0.8, 0], "radius": 0.8, "material": "globe"},
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "uv_scale": 3, "material": "floor"}]})");
    const Framebuffer ray = render_whitted(scene, Film(scene.camera));
    EXPECT_GT(testing::psnr(render_zbuffer(scene, Film(scene.camera)), ray), 30.0);
}

/// Mean and standard deviation of the grey of row `y` of `fb`.
std::pair<double, double> row_statistics(const Framebuffer& fb, int y) {
    const Image& image = fb.film.linear();
    double sum = 0, sum2 = 0;
    for (int x = 0; x < image.width; ++x) {
        const Vec3 c = image.at(x, y);
        const double g = (c.x + c.y + c.z) / 3.0;
        sum += g, sum2 += g * g;
    }
    const double mean = sum / image.width;
    return {mean, std::sqrt(std::max(0.0, sum2 / image.width - mean * mean))};
}

TEST(ShadeVisibility, GrazingCheckerFloorFadesToTheMeanInEveryMethod) {
    // scenes/checker-floor.json at 160 × 90: the horizon lies at row 42.6. Just below it the
    // floor's squares are far smaller than a pixel: every row there must be the texture's mean
    // grey, flat (no moiré), in both pipelines, and the two pipelines must agree overall.
    Scene scene = testing::scene_file("checker-floor.json", 160, 90);
    const MipPyramid& pyramid = *std::get<ImageTexture>(*scene.materials[0].texture).pyramid;
    const Vec3 mean = pyramid.levels.back().at(0, 0);
    const double grey = (mean.x + mean.y + mean.z) / 3.0;
    const Framebuffer ray = render_whitted(scene, Film(scene.camera));
    const Framebuffer z = render_zbuffer(scene, Film(scene.camera));
    EXPECT_GT(testing::psnr(z, ray), 30.0);
    for (const Framebuffer* fb : {&ray, &z})
        for (int y = 43; y < 47; ++y) {
            const auto [row_mean, row_deviation] = row_statistics(*fb, y);
            EXPECT_NEAR(row_mean, grey, 0.02) << "row " << y;
            EXPECT_LT(row_deviation, 0.02) << "row " << y;
        }
    // Without the pyramid the same rows alias: the test can tell.
    std::get<ImageTexture>(*scene.materials[0].texture).filter = TextureFilter::bilinear;
    const Framebuffer aliased = render_zbuffer(scene, Film(scene.camera));
    double worst = 0;
    for (int y = 43; y < 47; ++y) worst = std::max(worst, row_statistics(aliased, y).second);
    EXPECT_GT(worst, 0.1);
}

}  // namespace
}  // namespace hikari
