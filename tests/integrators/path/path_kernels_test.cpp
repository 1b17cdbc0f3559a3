// The wavefront path tracer's kernels (path_kernel.h), run on the CPU through the entry point the
// GPU uses (core/device_launch.h), against the CPU's own path tracer (render_path, its caustics
// left to the camera paths as the kernels leave them): both take the same Sobol' samples through
// the same estimator and sum each pixel's samples in the same order, so the images are the same
// to the bit, and so are the ids, depths and normals. These are the GPU's kernels, so this
// covers their code without a GPU.
#include "hikari/integrators/path/path_kernels.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <string>

#include "../../support/kernel_comparison.h"
#include "hikari/core/error.h"
#include "hikari/io/scene/scene_json.h"

namespace hikari {
namespace {

/// `samples` per pixel, `depth` bounces, caustics from the camera paths (the kernels' way).
PathSettings camera_caustics(int samples, int depth = 8) {
    PathSettings path;
    path.samples_per_pixel = samples;
    path.max_depth = depth;
    path.light_traced_caustics = false;
    return path;
}

/// The kernels on the CPU and render_path give `scene` the same pixels, ids, depths and normals.
void expect_path_kernels_match(const Scene& scene, const PathSettings& path) {
    RenderSettings settings;
    settings.aov_buffers = true;
    const Framebuffer reference = render_path(scene, Film(scene.camera), settings, path);
    const Framebuffer kernels =
        render_path_kernels(scene, Film(scene.camera), settings, path, ExecutionDevice::cpu);
    const testing::KernelDifferences d = testing::compare_kernel_render(kernels, reference, 0.0f);
    EXPECT_EQ(d.colour, 0u) << "largest difference " << d.largest;
    EXPECT_EQ(d.id, 0u);
    EXPECT_EQ(d.depth, 0u);
    EXPECT_EQ(d.normal, 0u);
    // Not a black image matching a black image.
    double sum = 0.0;
    for (const Vec3& c : kernels.film.linear().pixels) sum += c.x + c.y + c.z;
    EXPECT_GT(sum, 0.0);
}

TEST(PathKernels, CornellBoxMatchesThePathTracer) {
    // B5's scene: emissive triangles, light sampling and BSDF sampling weighed by MIS, Russian
    // roulette after three bounces.
    expect_path_kernels_match(testing::scene_file("bench/cornell.json", 40, 40),
                              camera_caustics(8));
}

TEST(PathKernels, GlassAndMirrorSpheresMatchThePathTracer) {
    // Delta lobes: caustics through the camera paths, emitters met after mirror chains.
    expect_path_kernels_match(testing::scene_file("cornell-glass.json", 32, 32),
                              camera_caustics(8, 12));
}

TEST(PathKernels, PointAndDirectionalLightsOnAMeshMatchThePathTracer) {
    // The teapot through the wide BVH, a point and a directional light, the plane and the sky.
    expect_path_kernels_match(testing::scene_file("teapot.json", 48, 36), camera_caustics(4));
    expect_path_kernels_match(testing::scene_file("shadows.json", 40, 30), camera_caustics(4));
}

TEST(PathKernels, SpotAndAreaLightsMatchThePathTracer) {
    expect_path_kernels_match(testing::scene_file("light-spot.json", 40, 30), camera_caustics(4));
    // The parallelogram light: its face met by rays, sampled by area, weighed by MIS.
    expect_path_kernels_match(testing::scene_file("area-light.json", 40, 30), camera_caustics(4));
    expect_path_kernels_match(testing::scene_file("soft-shadow.json", 40, 30), camera_caustics(4));
}

TEST(PathKernels, FiltersClampAndWavesMatchThePathTracer) {
    PathSettings path = camera_caustics(3);
    path.filter = PixelFilterKind::blackman_harris;
    path.clamp = 2.0f;
    expect_path_kernels_match(testing::scene_file("bench/cornell.json", 24, 24), path);
    // More samples than one wave holds (2^20 paths): a wave of 16 samples of 256² pixels, then
    // the one left over, summed on in sample order.
    path = camera_caustics(17, 0);
    path.filter = PixelFilterKind::gaussian;
    expect_path_kernels_match(testing::scene_file("bench/cornell.json", 256, 256), path);
}

TEST(PathKernels, ConstantEnvironmentLightMatchesThePathTracer) {
    // Light from the whole sky: sampled by the cosine, met by escaping rays, weighed by MIS.
    Scene scene = testing::scene_file("teapot.json", 48, 36);
    scene.lights.push_back(EnvironmentLight{.radiance = {0.3f, 0.4f, 0.6f}});
    expect_path_kernels_match(scene, camera_caustics(4));
}

TEST(PathKernels, CheckerTexturesMatchThePathTracer) {
    Scene scene = testing::scene_file("cornell-glass.json", 32, 32);
    scene.materials[0].texture = CheckerTexture{
        .size = 100.0f, .color_a = {0.1f, 0.1f, 0.1f}, .color_b = {0.9f, 0.9f, 0.9f}};
    expect_path_kernels_match(scene, camera_caustics(4));
}

TEST(PathKernels, SameImageForAnyThreadCount) {
    const Scene scene = testing::scene_file("cornell-glass.json", 32, 32);
    const PathSettings path = camera_caustics(4);
    Framebuffer one, two;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = render_path_kernels(scene, Film(scene.camera), {}, path, ExecutionDevice::cpu);
    }
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        two = render_path_kernels(scene, Film(scene.camera), {}, path, ExecutionDevice::cpu);
    }
    EXPECT_EQ(one.film.linear().pixels, two.film.linear().pixels);
    const Framebuffer many =
        render_path_kernels(scene, Film(scene.camera), {}, path, ExecutionDevice::cpu);
    EXPECT_EQ(one.film.linear().pixels, many.film.linear().pixels);
}

TEST(PathKernels, StatsCountTheRaysAndPaths) {
    const Scene scene = testing::scene_file("bench/cornell.json", 16, 16);
    RenderStats kernels_stats, reference_stats;
    RenderSettings settings;
    settings.stats = &kernels_stats;
    render_path_kernels(scene, Film(scene.camera), settings, camera_caustics(2),
                        ExecutionDevice::cpu);
    settings.stats = &reference_stats;
    render_path(scene, Film(scene.camera), settings, camera_caustics(2));
    EXPECT_EQ(kernels_stats.paths_traced.load(), 16u * 16u * 2u);
    EXPECT_EQ(kernels_stats.rays_traced.load(), reference_stats.rays_traced.load());
}

TEST(PathKernels, ScenesAndSettingsTheKernelsLackAreRefusedByName) {
    const Scene cornell = testing::scene_file("bench/cornell.json", 8, 8);
    EXPECT_EQ(path_kernel_refusal(cornell, {}), "");
    Scene sky = cornell;
    sky.lights.push_back(EnvironmentLight{});
    EXPECT_EQ(path_kernel_refusal(sky, {}), "");
    const Scene mapped = testing::scene_file("environment.json", 8, 8);
    EXPECT_NE(path_kernel_refusal(mapped, {}).find("environment maps"), std::string::npos);
    EXPECT_THROW(render_path_kernels(mapped, Film(mapped.camera), {}, {}, ExecutionDevice::cpu),
                 InputError);
    Scene textured = cornell;
    textured.materials[0].texture = ImageTexture{};
    EXPECT_NE(path_kernel_refusal(textured, {}).find("image textures"), std::string::npos);
    PathSettings timed;
    timed.time_limit_seconds = 1.0f;
    EXPECT_NE(path_kernel_refusal(cornell, timed).find("--time-limit"), std::string::npos);
    PathSettings progressive;
    progressive.progressive_seconds = 1.0f;
    EXPECT_NE(path_kernel_refusal(cornell, progressive).find("--progressive"), std::string::npos);
}

// The GPU test (scripts/gpu-check.sh runs it on a GPU machine; skipped without a device): the
// same kernels as CUDA grids give the CPU run's ids, depths and normals, and its image up to the
// GPU's rounding of sqrt, pow, sin and cos (its libm is not glibc's), which moves a few paths
// onto other branches: the means agree within their noise, most pixels within 1e-3.
TEST(PathKernels, CudaGridMatchesTheCpuRun) {
    if (!find_cuda_devices().problem.empty()) GTEST_SKIP() << find_cuda_devices().problem;
    for (const Scene& scene : {testing::scene_file("bench/cornell.json", 64, 64),
                               testing::scene_file("teapot.json", 64, 48),
                               testing::scene_file("area-light.json", 64, 48)}) {
        RenderSettings settings;
        settings.aov_buffers = true;
        const PathSettings path = camera_caustics(16);
        const Framebuffer cpu =
            render_path_kernels(scene, Film(scene.camera), settings, path, ExecutionDevice::cpu);
        const Framebuffer gpu =
            render_path_kernels(scene, Film(scene.camera), settings, path, ExecutionDevice::cuda);
        const testing::KernelDifferences d = testing::compare_kernel_render(gpu, cpu, 0.0f);
        EXPECT_EQ(d.id, 0u);
        double cpu_mean = 0.0, gpu_mean = 0.0;
        size_t close = 0;
        const auto& a = cpu.film.linear().pixels;
        const auto& b = gpu.film.linear().pixels;
        for (size_t i = 0; i < a.size(); ++i) {
            cpu_mean += (a[i].x + a[i].y + a[i].z) / (3.0 * a.size());
            gpu_mean += (b[i].x + b[i].y + b[i].z) / (3.0 * b.size());
            float worst = 0.0f;
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst,
                                 std::abs(a[i][c] - b[i][c]) / std::max(1.0f, std::abs(a[i][c])));
            close += worst <= 1e-3f ? 1 : 0;
        }
        EXPECT_NEAR(gpu_mean, cpu_mean, 0.01 * cpu_mean + 1e-6);
        EXPECT_GE(close, a.size() * 9 / 10);
    }
}

TEST(PathKernels, CudaWithoutADeviceSaysSoInOneLine) {
    const Scene scene = testing::scene_file("bench/cornell.json", 8, 8);
    testing::expect_no_device_in_one_line(
        [&] { render_path_kernels(scene, Film(scene.camera), {}, {}, ExecutionDevice::cuda); });
}

}  // namespace
}  // namespace hikari
