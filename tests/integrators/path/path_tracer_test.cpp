// The path tracer's physically based answers: a white furnace, a plane under the sky, the
// Cornell box, thread-count independence, bad samples, and what it says about materials.
#include "hikari/integrators/path/path_tracer.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "../../io/scene_test_util.h"
#include "hikari/core/color.h"

namespace hikari {
namespace {

using testing::parse;

/// The linear image of `scene` path-traced with `spp` samples and `depth` bounces.
Image render(const Scene& scene, int spp, int depth = 8, RenderStats* stats = nullptr) {
    PathSettings path;
    path.samples_per_pixel = spp;
    path.max_depth = depth;
    RenderSettings settings;
    settings.aov_buffers = false;
    settings.stats = stats;
    return render_path(scene, Film(scene.camera, FilmFormat::linear), settings, path).film.linear();
}

Vec3 mean_of(const Image& image) {
    Vec3 sum(0.0f);
    for (const Vec3& p : image.pixels) sum += p;
    return sum / static_cast<float>(image.pixels.size());
}

TEST(PathTracer, WhiteFurnaceSphereIsInvisible) {
    // A sphere of albedo 1 inside a constant environment of radiance 1 reflects exactly what it
    // receives: every pixel, sphere or sky, is 1.
    for (const char* material : {R"({"kd": 1})", R"({"kd": 0.5, "ks": 0.5, "shininess": 20})"}) {
        const Scene scene = parse(std::string(R"({
          "camera": {"eye": [0, 0, 3], "look_at": [0, 0, 0], "fov_y": 50, "width": 24, "height": 24},
          "materials": {"white": )") +
                                  material + R"(},
          "lights": [{"type": "environment", "radiance": 1}],
          "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "white"}]})");
        const Image image = render(scene, 64);
        for (const Vec3& p : image.pixels) {
            if (std::string(material).find("ks") == std::string::npos) {
                // Lambert: light and BSDF sampling both draw by the cosine, so no noise at all.
                EXPECT_NEAR(p.x, 1.0f, 1e-3f);
            } else {
                // Phong: the lobe loses light at grazing angles (never gains), noise aside.
                EXPECT_LT(p.x, 1.05f);
                EXPECT_GT(p.x, 0.6f);
            }
        }
    }
}

TEST(PathTracer, DiffusePlaneUnderAConstantSkyReflectsKdTimesL) {
    // kd/π · L · π = kd·L (the lecture's model would give kd·L·π).
    const Scene scene = parse(R"({
      "camera": {"eye": [0, 1, 0], "look_at": [0, 0, -0.2], "fov_y": 40, "width": 16, "height": 16},
      "materials": {"grey": {"kd": [0.5, 0.25, 0.8]}},
      "lights": [{"type": "environment", "radiance": 2}],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "grey"}]})");
    const Image image = render(scene, 32);
    for (const Vec3& p : image.pixels) {
        EXPECT_NEAR(p.x, 1.0f, 1e-3f);
        EXPECT_NEAR(p.y, 0.5f, 1e-3f);
        EXPECT_NEAR(p.z, 1.6f, 1e-3f);
    }
}

/// The Cornell box of bench B5 at `size` pixels square.
Scene cornell(int size) {
    std::ifstream in(std::string(HIKARI_SOURCE_DIR) + "/scenes/bench/cornell.json");
    std::stringstream text;
    text << in.rdbuf();
    Scene scene = parse(text.str());
    scene.camera.width = scene.camera.height = size;
    return scene;
}

/// The mean sRGB value of `image` (each pixel encoded as 8 bits, as a PNG keeps it).
Vec3 mean_srgb(const Image& image) {
    Vec3 sum(0.0f);
    for (const Vec3& p : image.pixels)
        for (int a = 0; a < 3; ++a) sum[a] += std::round(255.0f * linear_to_srgb(p[a])) / 255.0f;
    return sum / static_cast<float>(image.pixels.size());
}

TEST(PathTracer, CornellBoxMeanPixelMatchesCycles) {
    // Cycles 3.4 renders the same scene to a mean sRGB pixel of (0.3108, 0.2329, 0.1010) at
    // 512², 64 spp; at 96² the mean moves by noise and edges, well within 0.01.
    const Vec3 mean = mean_srgb(render(cornell(96), 64));
    EXPECT_NEAR(mean.x, 0.3108f, 0.01f);
    EXPECT_NEAR(mean.y, 0.2329f, 0.01f);
    EXPECT_NEAR(mean.z, 0.1010f, 0.01f);
}

/// The mean of `image` with each channel clamped to 1 (the light's own pixels, 17 times
/// brighter than white, would drown the rest).
Vec3 mean_clamped(const Image& image) {
    Vec3 sum(0.0f);
    for (const Vec3& p : image.pixels) sum += min(p, Vec3(1.0f));
    return sum / static_cast<float>(image.pixels.size());
}

TEST(PathTracer, BouncesAddIndirectLight) {
    const Scene scene = cornell(32);
    const float direct = mean_clamped(render(scene, 16, 0)).x;
    const float one = mean_clamped(render(scene, 16, 1)).x;
    const float all = mean_clamped(render(scene, 16, 8)).x;
    EXPECT_GT(direct, 0.02f);
    EXPECT_GT(one, direct * 1.2f);
    EXPECT_GT(all, one);
}

TEST(PathTracer, ImagesDoNotDependOnTheThreadCount) {
    const Scene scene = parse(R"({
      "camera": {"eye": [0, 1.5, 5], "look_at": [0, 0.8, 0], "fov_y": 45, "width": 40, "height": 30},
      "materials": {"floor": {"kd": 0.6}, "glass": {"transparency": 1, "ior": 1.5},
                    "mirror": {"reflectivity": 0.9}, "clay": {"kd": [0.6, 0.3, 0.2], "ks": 0.3, "shininess": 30}},
      "lights": [{"type": "area", "corner": [-1, 4, -1], "edge1": [2, 0, 0], "edge2": [0, 0, 2], "radiance": 6}],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
                  {"type": "sphere", "center": [-0.8, 0.7, 0], "radius": 0.7, "material": "glass"},
                  {"type": "sphere", "center": [0.9, 0.7, -0.5], "radius": 0.7, "material": "mirror"},
                  {"type": "sphere", "center": [0.2, 0.3, 1.2], "radius": 0.3, "material": "clay"}]})");
    Image one, two;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = render(scene, 24);
    }
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        two = render(scene, 24);
    }
    ASSERT_EQ(one.pixels.size(), two.pixels.size());
    for (size_t i = 0; i < one.pixels.size(); ++i) ASSERT_EQ(one.pixels[i], two.pixels[i]) << i;
    // The glass and the mirror show something: the image is not flat.
    EXPECT_GT(max_component(mean_of(one)), 0.05f);
}

TEST(PathTracer, EmissiveSpheresAndTrianglesAreSeenAndLight) {
    const Scene scene = parse(R"({
      "camera": {"eye": [0, 0, 4], "look_at": [0, 0, 0], "fov_y": 40, "width": 16, "height": 16},
      "materials": {"lamp": {"emission": [3, 2, 1]}, "floor": {"kd": 0.5}},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 0.5, "material": "lamp"},
                  {"type": "triangle", "vertices": [[-9, -1, 9], [9, -1, 9], [0, -1, -9]], "material": "floor"}]})");
    const Image image = render(scene, 16);
    const Vec3 centre = image.at(8, 8);
    EXPECT_NEAR(centre.x, 3.0f, 1e-4f);
    EXPECT_NEAR(centre.z, 1.0f, 1e-4f);
    // The floor below the sphere is lit by it (found by BSDF sampling alone: spheres are not
    // light-sampled).
    EXPECT_GT(image.at(8, 15).x, 0.0f);
}

TEST(PathTracer, NonFiniteSamplesAreCountedAndLeftOut) {
    // Radiance beyond the float range: the emitter seen directly plus the sky it reflects
    // overflow to infinity.
    const Scene scene = parse(R"({
      "camera": {"eye": [0, 1, 0], "look_at": [0, 0, -0.2], "fov_y": 40, "width": 8, "height": 8},
      "materials": {"hot": {"kd": 1, "emission": 3e38}},
      "lights": [{"type": "environment", "radiance": 3e38}],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "hot"}]})");
    RenderStats stats;
    const Image image = render(scene, 4, 8, &stats);
    EXPECT_GT(stats.bad_samples.load(), 0U);
    for (const Vec3& p : image.pixels) EXPECT_TRUE(is_finite(p));
    EXPECT_EQ(stats.paths_traced.load(), 8U * 8U * 4U);
}

TEST(PathTracer, WarnsOfMaterialsThatCreateLight) {
    const Scene scene = parse(R"({
      "materials": {"fine": {"kd": 0.5, "ks": 0.5}, "bright": {"kd": 0.8, "ks": 0.5}},
      "objects": [{"type": "sphere", "center": [0, 0, -3], "radius": 1, "material": "bright"}]})");
    const std::vector<std::string> warnings = path_scene_warnings(scene);
    ASSERT_EQ(warnings.size(), 1U);
    EXPECT_NE(warnings[0].find("'bright'"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("1.3"), std::string::npos) << warnings[0];
}

TEST(PathTracer, ProgressiveSnapshotsShowTheSamplesSoFar) {
    const Scene scene = cornell(16);
    PathSettings path;
    path.samples_per_pixel = 4096;
    path.progressive_seconds = 1e-6f;  // after every pass
    int calls = 0, last = 0;
    path.snapshot = [&](const Image& mean, int samples) {
        EXPECT_GT(samples, last);
        EXPECT_EQ(mean.width, 16);
        last = samples;
        ++calls;
    };
    path.time_limit_seconds = 0.3f;
    const Framebuffer fb = render_path(scene, Film(scene.camera, FilmFormat::linear), {}, path);
    EXPECT_GT(calls, 2);
    EXPECT_TRUE(is_finite(mean_of(fb.film.linear())));
}

}  // namespace
}  // namespace hikari
