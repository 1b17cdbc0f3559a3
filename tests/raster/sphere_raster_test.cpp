#include "hikari/raster/sphere_raster.h"

#include <gtest/gtest.h>

#include <string>

#include <fmt/format.h>
#include <tbb/global_control.h>

#include "hikari/integrators/whitted/whitted.h"
#include "hikari/raster/shade_visibility.h"
#include "hikari/raster/zbuffer.h"
#include "raster_test_util.h"

namespace hikari {
namespace {

/// A scene of `objects` seen by `camera` (JSON), one directional light, no shadows asked.
Scene scene_with(const std::string& camera, const std::string& objects) {
    return testing::raster_scene_from(fmt::format(R"({{
      "camera": {},
      "background": [0.1, 0.2, 0.3], "ambient": [0.1, 0.1, 0.1],
      "materials": {{
        "red": {{"ka": [0.8, 0.2, 0.2], "kd": [0.7, 0.2, 0.2], "ks": [0.5, 0.5, 0.5], "shininess": 30}},
        "grey": {{"ka": [0.5, 0.5, 0.5], "kd": [0.6, 0.6, 0.6]}}}},
      "lights": [{{"type": "directional", "direction": [-0.4, -1, -0.6], "intensity": [1, 1, 1]}}],
      "objects": [{}]}})",
                                                  camera, objects));
}

/// Spheres partly off-screen, overlapping, intersecting one another, one behind the eye.
const std::string k_spheres = R"(
  {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "red"},
  {"type": "sphere", "center": [1.2, 0.3, -0.5], "radius": 0.8, "material": "grey"},
  {"type": "sphere", "center": [-0.9, -0.2, 0.6], "radius": 0.5, "material": "grey"},
  {"type": "sphere", "center": [-3.3, 1.8, -1], "radius": 1.5, "material": "red"},
  {"type": "sphere", "center": [0, 0, 9], "radius": 0.5, "material": "red"},
  {"type": "sphere", "center": [0.4, -1.1, 0.9], "radius": 0.3, "material": "red"})";

const std::string k_cameras[] = {
    R"({"eye": [0, 0, 5], "look_at": [0, 0, 0], "fov_y": 50, "width": 80, "height": 60})",
    R"({"eye": [2.5, 3, 4], "look_at": [0.2, 0, 0], "fov_y": 70, "width": 71, "height": 53})",
    R"({"eye": [0.3, 0.1, 1.7], "look_at": [0, 0, 0], "fov_y": 90, "width": 64, "height": 64})",
    R"({"eye": [1, 2, 6], "look_at": [0, 0, 0], "projection": "orthographic",
        "view_height": 5, "width": 70, "height": 50})"};

int64_t id_mismatches(const Framebuffer& a, const Framebuffer& b) {
    int64_t n = 0;
    for (size_t i = 0; i < a.id.size(); ++i) n += a.id[i] != b.id[i];
    return n;
}

int64_t seen(const Framebuffer& fb) {
    int64_t n = 0;
    for (const uint32_t id : fb.id) n += id != 0;
    return n;
}

TEST(SphereRaster, IdBufferEqualsTheRayTracersOnSphereScenes) {
    for (const std::string& camera : k_cameras) {
        const Scene scene = scene_with(camera, k_spheres);
        const Framebuffer ray = render_whitted(scene, Film(scene.camera));
        const Framebuffer z = render_zbuffer(scene, Film(scene.camera));
        EXPECT_GT(seen(z), 100) << camera;
        EXPECT_EQ(id_mismatches(z, ray), 0) << camera;
    }
}

TEST(SphereRaster, EverySphereAPixelMeetsIsOneFragmentInTheStats) {
    // Two overlapping spheres drawn together test as many fragments as each covers alone.
    const std::string camera = k_cameras[0];
    const std::string front = R"({"type": "sphere", "center": [0, 0, 0], "radius": 1,
                                  "material": "red"})";
    const std::string back = R"({"type": "sphere", "center": [0.8, 0.3, -2], "radius": 1.2,
                                 "material": "grey"})";
    const auto stats_of = [&](const std::string& objects, uint64_t& covered, uint64_t& spheres) {
        const Scene scene = scene_with(camera, objects);
        RenderStats stats;
        RenderSettings settings;
        settings.stats = &stats;
        render_zbuffer(scene, Film(scene.camera), settings);
        covered = stats.raster_covered_pixels.load();
        spheres = stats.raster_exact_spheres.load();
        return stats.raster_fragments.load();
    };
    uint64_t covered_front = 0, covered_back = 0, covered_both = 0, spheres = 0;
    EXPECT_EQ(stats_of(front, covered_front, spheres), covered_front);
    EXPECT_EQ(spheres, 1u);
    EXPECT_EQ(stats_of(back, covered_back, spheres), covered_back);
    const uint64_t both = stats_of(front + "," + back, covered_both, spheres);
    EXPECT_EQ(spheres, 2u);
    EXPECT_EQ(both, covered_front + covered_back);
    EXPECT_LT(covered_both, both);  // they overlap on screen
}

TEST(SphereRaster, IdBufferEqualsTheRayTracersWithAFloor) {
    // Spheres resting just above a plane (tessellated, as triangles): where they do not meet
    // it, every pixel sees what the ray tracer sees.
    const std::string objects = k_spheres + R"(,
      {"type": "plane", "point": [0, -1.5, 0], "normal": [0, 1, 0], "material": "grey"})";
    for (const std::string& camera : k_cameras) {
        const Scene scene = scene_with(camera, objects);
        const Framebuffer ray = render_whitted(scene, Film(scene.camera));
        const Framebuffer z = render_zbuffer(scene, Film(scene.camera));
        EXPECT_EQ(id_mismatches(z, ray), 0) << camera;
    }
}

TEST(SphereRaster, EyeInsideASphereSeesItsInside) {
    // The ray tracer sees the inner wall of a sphere around the eye (the far root); so does the
    // Z-buffer, and a sphere inside it in front.
    const Scene scene = scene_with(
        R"({"eye": [0, 0, 0.5], "look_at": [0, 0, -1], "fov_y": 60, "width": 48, "height": 40})",
        R"({"type": "sphere", "center": [0, 0, 0], "radius": 3, "material": "grey"},
           {"type": "sphere", "center": [0.3, 0, -1.5], "radius": 0.5, "material": "red"})");
    const Framebuffer ray = render_whitted(scene, Film(scene.camera));
    const Framebuffer z = render_zbuffer(scene, Film(scene.camera));
    EXPECT_EQ(seen(z), 48 * 40);
    EXPECT_EQ(id_mismatches(z, ray), 0);
}

TEST(SphereRaster, ColoursCloseToTheRayTracers) {
    // No shadows, no mirrors: the same surface points and normals shaded by the same model.
    for (const std::string& camera : k_cameras) {
        Scene scene = scene_with(camera, k_spheres);
        WhittedSettings no_shadows;
        no_shadows.shadow_rays = false;
        const Framebuffer ray = render_whitted(scene, Film(scene.camera), {}, no_shadows);
        const Framebuffer z = render_zbuffer(scene, Film(scene.camera));
        EXPECT_GT(testing::psnr(z, ray), 60.0) << camera;
        for (size_t i = 0; i < z.normal.size(); ++i)
            if (z.id[i] != 0) {
                EXPECT_NEAR(z.depth[i], ray.depth[i], 1e-4f * ray.depth[i]) << camera;
                EXPECT_NEAR(dot(z.normal[i], ray.normal[i]), 1.0f, 1e-5f) << camera;
            }
    }
}

TEST(SphereRaster, TheSameForAnyThreadCount) {
    const Scene scene = scene_with(k_cameras[1], k_spheres + R"(,
      {"type": "plane", "point": [0, -1.5, 0], "normal": [0, 1, 0], "material": "grey"})");
    RasterSettings raster;
    raster.shadows = ShadowMode::map;
    raster.shadow_map_size = 256;
    Framebuffer one;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = render_zbuffer(scene, Film(scene.camera), {}, raster);
    }
    Framebuffer two;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        two = render_zbuffer(scene, Film(scene.camera), {}, raster);
    }
    EXPECT_EQ(one.film.linear().pixels, two.film.linear().pixels);
    EXPECT_EQ(one.id, two.id);
}

TEST(SphereRaster, BoundsHoldEverySilhouettePixel) {
    // Every pixel whose ray meets a sphere lies in the sphere's screen bound.
    const Scene scene = scene_with(k_cameras[1], k_spheres);
    const ProjectedScene ps = project_scene(scene, {}, SphereGeometry::exact);
    ASSERT_EQ(ps.scene.spheres.size(), 6u);
    const SphereRaster raster = prepare_sphere_raster(ps.scene.spheres, ps.view,
                                                      camera_pixel_rays(scene.camera, ps.view), 0);
    int hits = 0;
    for (size_t k = 0; k < raster.spheres.size(); ++k)
        for (int y = 0; y < scene.camera.height; ++y)
            for (int x = 0; x < scene.camera.width; ++x) {
                Ray ray;
                if (!(pixel_sphere_hit(raster.rays, raster.spheres[k], x, y, ray) >= 0.0f))
                    continue;
                ++hits;
                const PixelRect& b = raster.bounds[k];
                EXPECT_TRUE(x >= b.x0 && x < b.x1 && y >= b.y0 && y < b.y1) << k;
            }
    EXPECT_GT(hits, 500);
}

// A 90° face of a point light's cube map, as shadow maps make them: a small sphere beside the
// light reaches across the face's eye plane, but only its part beyond the near plane can be
// seen, and that projects to a few texels, not to the whole face (which made a cloud of small
// spheres around a point light cost seconds).
TEST(SphereRaster, ASphereAcrossTheEyePlaneIsBoundedByItsPartBeyondTheNearPlane) {
    RasterView face;
    face.width = face.height = 256;
    face.near_plane = 0.1f;
    face.view_from_world = look_at({0, 0, 0}, {0, 0, -1}, {0, 1, 0});
    face.clip_from_view = perspective(90, 1.0f, 0.1f, 100);
    face.screen_from_clip = viewport(256, 256);
    face.clip_from_world = face.clip_from_view * face.view_from_world;
    const std::vector<Sphere> spheres = {Sphere{{3, 0, 0.01f}, 0.05f},  // across the eye plane
                                         Sphere{{0, 0, 5}, 0.5f},       // behind the eye
                                         Sphere{{0.5f, 0, -4}, 0.2f}};  // in front
    const SphereRaster raster = prepare_sphere_raster(spheres, face, view_pixel_rays(face), 0);
    auto area = [](const PixelRect& r) { return (r.x1 - r.x0) * (r.y1 - r.y0); };
    EXPECT_LT(area(raster.bounds[0]), 256 * 256 / 16);
    EXPECT_EQ(area(raster.bounds[1]), 0);
    EXPECT_GT(area(raster.bounds[2]), 0);
    EXPECT_LT(area(raster.bounds[2]), 256 * 256 / 16);
    // Each sphere is listed in the tiles its bound meets, and only there.
    size_t listed = 0;
    for (const uint32_t k : raster.tile_spheres) listed += k == 2;
    EXPECT_GE(listed, 1u);
    EXPECT_LE(listed, 4u);
}

TEST(SphereRaster, RoundShadowOfASphereOnTheFloor) {
    // A sphere over a floor under a slanting light: its shadow-map shadow is the ellipse the
    // ray tracer's shadow rays find (up to the map's bias at the rim), not a polygon.
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0, 6, 0.01], "look_at": [0, 0, 0], "fov_y": 50, "width": 64, "height": 64},
      "ambient": [0, 0, 0], "materials": {"m": {"kd": [1, 1, 1]}},
      "lights": [{"type": "directional", "direction": [1, -1, 0], "intensity": [1, 1, 1]}],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "m"},
                  {"type": "sphere", "center": [-0.5, 1.5, 0], "radius": 0.4, "material": "m",
                   "casts_shadow": true}]})");
    RasterSettings raster;
    raster.shadows = ShadowMode::map;
    raster.shadow_map_size = 1024;
    const Framebuffer z = render_zbuffer(scene, Film(scene.camera), {}, raster);
    const Framebuffer ray = render_whitted(scene, Film(scene.camera));
    int differ = 0, dark = 0;
    for (size_t i = 0; i < z.id.size(); ++i) {
        if (z.id[i] != 1) continue;  // the floor
        const bool z_dark = z.film.linear().pixels[i][0] < 0.5f;
        const bool ray_dark = ray.film.linear().pixels[i][0] < 0.5f;
        differ += z_dark != ray_dark;
        dark += z_dark;
    }
    EXPECT_GT(dark, 20);
    EXPECT_LE(differ, 2);
}

}  // namespace
}  // namespace hikari
