// The Whitted kernel bodies (whitted_kernel.h), run on the CPU through the entry point the GPU
// uses (core/device_launch.h), against the CPU's own ray tracer (render_whitted): the same
// pixels up to the rounding of the order in which a ray tree's colours are summed, the same ids,
// depths and normals. These are the GPU's kernels, so this covers their code without a GPU.
#include "hikari/integrators/whitted/whitted_kernels.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <string>

#include "../../io/scene_test_util.h"
#include "../../support/kernel_comparison.h"
#include "hikari/core/error.h"
#include "hikari/io/scene/scene_json.h"

namespace hikari {
namespace {

using testing::parse;

/// The Whitted test scene of B3 (a mirror, a glass ball that casts no shadow, a Phong sphere, a
/// plane, a gradient sky), with its checker floor when `checker`.
Scene glass_and_mirror(int width, int height, bool checker = false) {
    const std::string floor =
        checker ? R"("floor": {"ka": 0.1, "kd": 0.8, "texture": {"type": "checker", "size": 1,
                    "color_a": [0.1, 0.1, 0.1], "color_b": [0.9, 0.9, 0.9], "offset": [0, 0.5, 0]}},)"
                : R"("floor": {"ka": 0.1, "kd": 0.8},)";
    return parse(R"({
      "camera": {"eye": [0, 2, 7], "look_at": [0, 1, 0], "up": [0, 1, 0], "fov_y": 45,
                 "width": )" +
                 std::to_string(width) + R"(, "height": )" + std::to_string(height) + R"(},
      "background": [0.8, 0.9, 1.0],
      "sky": {"type": "gradient", "horizon": [0.8, 0.9, 1.0], "zenith": [0.2, 0.4, 0.9]},
      "ambient": [1, 1, 1],
      "materials": {
        )" + floor +
                 R"(
        "mirror": {"reflectivity": 0.9},
        "glass": {"ks": 0.8, "shininess": 200, "reflectivity": 0.1, "transparency": 1, "ior": 1.5},
        "red": {"ka": [0.08, 0.015, 0.015], "kd": [0.56, 0.105, 0.105], "ks": 0.6, "shininess": 40}
      },
      "lights": [{"type": "point", "position": [-5, 8, 6], "intensity": [1, 1, 1], "falloff": "none"}],
      "objects": [
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
        {"type": "sphere", "center": [-2.2, 1, -1], "radius": 1, "material": "mirror"},
        {"type": "sphere", "center": [0, 1, 1], "radius": 1, "material": "glass", "casts_shadow": false},
        {"type": "sphere", "center": [2.2, 1, -1], "radius": 1, "material": "red"}
      ]})");
}

/// The kernels on the CPU and render_whitted agree on every pixel of `scene`: colours within
/// `tolerance` (1e-5: the sums' order), ids, depths and normals exactly.
void expect_kernels_match(const Scene& scene, const WhittedSettings& whitted = {},
                          float tolerance = 1e-5f) {
    const Framebuffer reference = render_whitted(scene, Film(scene.camera), {}, whitted);
    const Framebuffer kernels =
        render_whitted_kernels(scene, Film(scene.camera), {}, whitted, ExecutionDevice::cpu);
    const testing::KernelDifferences d =
        testing::compare_kernel_render(kernels, reference, tolerance);
    EXPECT_EQ(d.colour, 0u) << "largest difference " << d.largest;
    EXPECT_EQ(d.id, 0u);
    EXPECT_EQ(d.depth, 0u);
    EXPECT_EQ(d.normal, 0u);
}

TEST(WhittedKernels, AssignmentSphereMatchesTheRayTracer) {
    expect_kernels_match(testing::scene_file("assignment.json", 96, 72));
}

TEST(WhittedKernels, MirrorAndGlassMatchTheRayTracer) {
    expect_kernels_match(glass_and_mirror(160, 90));
}

TEST(WhittedKernels, CheckerFilteredOverRayConesMatchesTheRayTracer) {
    // The checker is box-filtered over each ray's cone, carried through mirror and glass.
    expect_kernels_match(glass_and_mirror(160, 90, true));
}

TEST(WhittedKernels, DeepTreesMatchTheRayTracer) {
    WhittedSettings deep;
    deep.max_depth = 12;  // glass between mirrors: trees of hundreds of rays
    expect_kernels_match(glass_and_mirror(64, 40), deep);
}

TEST(WhittedKernels, MeshesThroughTheWideBvhMatchTheRayTracer) {
    expect_kernels_match(testing::scene_file("teapot.json", 120, 90));
}

TEST(WhittedKernels, ShadowsAndSpotLightsMatchTheRayTracer) {
    expect_kernels_match(testing::scene_file("shadows.json", 100, 75));
    expect_kernels_match(testing::scene_file("light-spot.json", 100, 75));
}

TEST(WhittedKernels, NoShadowsAndJitteredSamplesMatchTheRayTracer) {
    WhittedSettings settings;
    settings.shadow_rays = false;
    expect_kernels_match(glass_and_mirror(80, 45), settings);
    settings.shadow_rays = true;
    settings.samples_per_pixel = 4;
    expect_kernels_match(glass_and_mirror(80, 45), settings);
}

TEST(WhittedKernels, SameImageForAnyThreadCount) {
    const Scene scene = glass_and_mirror(64, 36);
    Framebuffer one, two;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = render_whitted_kernels(scene, Film(scene.camera), {}, {}, ExecutionDevice::cpu);
    }
    two = render_whitted_kernels(scene, Film(scene.camera), {}, {}, ExecutionDevice::cpu);
    EXPECT_EQ(one.film.linear().pixels, two.film.linear().pixels);
}

TEST(WhittedKernels, ScenesTheKernelsLackAreRefusedByName) {
    Scene scene = glass_and_mirror(8, 8);
    scene.lights.push_back(AreaLight{{0, 4, 0}, {1, 0, 0}, {0, 0, 1}, {1, 1, 1}});
    EXPECT_NE(whitted_kernel_refusal(scene, {}).find("area lights"), std::string::npos);
    EXPECT_THROW(render_whitted_kernels(scene, Film(scene.camera), {}, {}, ExecutionDevice::cpu),
                 InputError);
    Scene textured = glass_and_mirror(8, 8);
    textured.materials[0].texture = ImageTexture{};
    EXPECT_NE(whitted_kernel_refusal(textured, {}).find("image textures"), std::string::npos);
    textured.materials[0].texture = CheckerTexture{};
    EXPECT_EQ(whitted_kernel_refusal(textured, {}), "");
    EXPECT_EQ(whitted_kernel_refusal(glass_and_mirror(8, 8), {}), "");
}

// The GPU test (scripts/gpu-check.sh runs it on a GPU machine; skipped without a device): the
// same kernels as a CUDA grid give the CPU run's ids, depths and normals, and its colours within
// the GPU's rounding of sqrt, pow and cos (its libm is not glibc's).
TEST(WhittedKernels, CudaGridMatchesTheCpuRun) {
    if (!find_cuda_devices().problem.empty()) GTEST_SKIP() << find_cuda_devices().problem;
    for (const Scene& scene :
         {glass_and_mirror(160, 90, true), testing::scene_file("teapot.json", 120, 90),
          testing::scene_file("shadows.json", 100, 75)}) {
        const Framebuffer cpu =
            render_whitted_kernels(scene, Film(scene.camera), {}, {}, ExecutionDevice::cpu);
        const Framebuffer gpu =
            render_whitted_kernels(scene, Film(scene.camera), {}, {}, ExecutionDevice::cuda);
        const testing::KernelDifferences d = testing::compare_kernel_render(gpu, cpu, 1e-3f);
        EXPECT_EQ(d.colour, 0u) << "largest difference " << d.largest;
        // A hit exactly on a shared edge may go to either triangle under other rounding: none of
        // these scenes has one at a pixel centre, so the ids are held exact.
        EXPECT_EQ(d.id, 0u);
    }
}

TEST(WhittedKernels, CudaWithoutADeviceSaysSoInOneLine) {
    const Scene scene = glass_and_mirror(8, 8);
    testing::expect_no_device_in_one_line(
        [&] { render_whitted_kernels(scene, Film(scene.camera), {}, {}, ExecutionDevice::cuda); });
}

}  // namespace
}  // namespace hikari
