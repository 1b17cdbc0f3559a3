// The orthographic camera (parallel projection) in every method: a sphere is a circle of its
// exact radius in pixels wherever it stands, and depth is measured from the image plane.

#include <cmath>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "../io/scene_test_util.h"
#include "hikari/methods/registry.h"

namespace hikari {
namespace {

constexpr int k_image_size = 64;
constexpr float k_view_height = 4.0f;

/// A sphere of radius `r` at `centre` under an orthographic camera looking down −z from z = 10.
Scene ortho_scene(Vec3 centre, float r) {
    return testing::parse(fmt::format(
        R"({{"camera": {{"eye": [0, 0, 10], "look_at": [0, 0, 0], "projection": "orthographic",
             "view_height": {}, "width": {}, "height": {}}},
            "lights": [{{"type": "directional", "direction": [0, 0, -1], "intensity": 1}}],
            "objects": [{{"type": "sphere", "center": [{}, {}, {}], "radius": {}}}]}})",
        k_view_height, k_image_size, k_image_size, centre.x, centre.y, centre.z, r));
}

Framebuffer render_aovs(const std::string& method, const Scene& scene) {
    RenderSettings settings;
    settings.aov_buffers = true;
    MethodSettings own;
    own.raster.shadow_map_size = 256;
    return render_scene(*find_method(method), scene, Film(scene.camera, FilmFormat::linear),
                        settings, own);
}

/// Pixels whose coverage differs from the exact disc of radius r (world units) about the
/// image point of `centre`, ignoring pixel centres within `band` pixels of the circle.
int disc_mismatches(const Framebuffer& fb, Vec3 centre, float r, float band) {
    const float px_per_unit = k_image_size / k_view_height;
    const float cx = k_image_size / 2.0f + centre.x * px_per_unit;
    const float cy = k_image_size / 2.0f - centre.y * px_per_unit;
    const float radius = r * px_per_unit;
    int wrong = 0;
    for (int y = 0; y < k_image_size; ++y)
        for (int x = 0; x < k_image_size; ++x) {
            const float d = std::hypot(x + 0.5f - cx, y + 0.5f - cy);
            if (std::abs(d - radius) < band) continue;
            const bool inside = d < radius;
            const bool seen = fb.id[static_cast<size_t>(y) * k_image_size + x] != k_background_id;
            wrong += inside != seen;
        }
    return wrong;
}

TEST(OrthographicCamera, SphereIsACircleOfItsExactRadiusInEveryMethod) {
    // Radius 1.3 world units = 20.8 pixels, off centre; the raster methods' polygons lie within
    // 0.05 px of the circle (raster/tessellate.h), the ray tracer meets it exactly.
    const Vec3 centre(0.3f, -0.2f, 0.0f);
    const Scene scene = ortho_scene(centre, 1.3f);
    for (const char* method : {"raytrace", "path", "zbuffer", "scanline", "depthsort"}) {
        const float band =
            std::string(method) == "raytrace" || std::string(method) == "path" ? 1e-3f : 0.06f;
        EXPECT_EQ(disc_mismatches(render_aovs(method, scene), centre, 1.3f, band), 0) << method;
    }
}

TEST(OrthographicCamera, SizeDoesNotDependOnDistance) {
    // Parallel projection: the same sphere moved away from the camera covers the same pixels.
    const Framebuffer near = render_aovs("raytrace", ortho_scene(Vec3(0, 0, 5), 1.0f));
    const Framebuffer far = render_aovs("raytrace", ortho_scene(Vec3(0, 0, -20), 1.0f));
    EXPECT_EQ(near.id, far.id);
}

TEST(OrthographicCamera, DepthIsTheDistanceFromTheImagePlane) {
    // The sphere's nearest point (0, 0, 1) is 9 units in front of the plane z = 10, and the
    // pixels beside the centre see points at the same distance whatever their lateral offset.
    for (const char* method : {"raytrace", "zbuffer"}) {
        const Framebuffer fb = render_aovs(method, ortho_scene(Vec3(0.0f), 1.0f));
        const size_t centre =
            static_cast<size_t>(k_image_size / 2) * k_image_size + k_image_size / 2;
        const float pixel = k_view_height / k_image_size;
        const float expected = 10.0f - std::sqrt(1.0f - 0.5f * pixel * pixel);
        // The raster sphere is polygons within 0.05 px (0.003 units here) inside the sphere.
        EXPECT_NEAR(fb.depth[centre], expected, 5e-3f) << method;
    }
}

TEST(OrthographicCamera, LineMethodsDrawTheSphere) {
    const Scene scene = ortho_scene(Vec3(0.0f), 1.0f);
    for (const char* method : {"wireframe", "hiddenline"}) {
        const LineDrawing d = draw_scene(*find_method(method), scene, MethodSettings{});
        EXPECT_GT(d.segments.size(), 10u) << method;
        for (const LineSegment& s : d.segments) {
            // Every end lies within the sphere's disc in the image.
            for (const Vec2 p : {s.a, s.b})
                EXPECT_LT(std::hypot(p.x - k_image_size / 2.0f, p.y - k_image_size / 2.0f), 16.5f)
                    << method;
        }
    }
}

TEST(OrthographicCamera, ViewHeightDefaultsToWhatThePinholeShowsAtLookAt) {
    // 2 · 4 · tan(30°): the look_at plane's extent in a 60° perspective view from 4 units.
    const Scene s = testing::parse(R"({"camera": {"eye": [0, 0, 4], "look_at": [0, 0, 0],
        "projection": "orthographic", "fov_y": 60}, "objects": []})");
    EXPECT_NEAR(s.camera.view_height, 8.0f * std::tan(3.14159265f / 6.0f), 1e-5f);
    // Each projection keeps its own key: a perspective camera may carry a view height.
    EXPECT_EQ(testing::error_of(R"({"camera": {"view_height": 3}, "objects": []})"), "");
}

TEST(OrthographicCamera, SceneFileErrors) {
    EXPECT_NE(testing::error_of(R"({"camera": {"projection": "orthographic", "view_height": 0},
                                    "objects": []})")
                  .find("camera.view_height"),
              std::string::npos);
    EXPECT_NE(testing::error_of(R"({"camera": {"projection": "fisheye"}, "objects": []})")
                  .find("camera.projection"),
              std::string::npos);
}

}  // namespace
}  // namespace hikari
