// The Z-buffer kernels (raster/zbuffer_kernel.h), run on the CPU through the entry point the GPU
// uses (core/device_launch.h), against the CPU's own Z-buffer (render_zbuffer, zbuffer_draw): the
// same triangle at every pixel and the same depths, bit for bit (the same fill rule and depth
// interpolation), colours within 1e-5, the same AOVs. These are the GPU's kernels, so this covers
// their code without a GPU.
#include "hikari/raster/zbuffer_kernels.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "../io/scene_test_util.h"
#include "../support/kernel_comparison.h"
#include "hikari/core/error.h"
#include "hikari/io/scene/scene_json.h"
#include "hikari/raster/vertex_pipeline.h"
#include "hikari/raster/zbuffer.h"

namespace hikari {
namespace {

using testing::parse;

/// A scene file of scenes/, at `width` × `height`; its spheres as polygons of `segments` when
/// that is set (else drawn exactly).
Scene scene_file(const std::string& name, int width, int height, uint32_t segments = 0) {
    Scene scene = testing::scene_file(name, width, height);
    for (Sphere& s : scene.spheres) s.segments = segments;
    return scene;
}

/// A checker floor, a checkered sphere and the vertex-coloured octahedron of
/// scenes/models/vertex-colours.obj under a spot light.
Scene checker_and_vertex_colours(int width, int height) {
    Scene scene = parse(R"({
      "camera": {"eye": [0, 2.5, 6], "look_at": [0, 0.6, 0], "up": [0, 1, 0], "fov_y": 45,
                 "width": )" +
                        std::to_string(width) + R"(, "height": )" + std::to_string(height) + R"(},
      "background": [0.2, 0.2, 0.25],
      "ambient": [0.2, 0.2, 0.2],
      "materials": {
        "floor": {"ka": 0.2, "kd": 0.8, "texture": {"type": "checker", "size": 0.5,
                  "color_a": [0.1, 0.1, 0.1], "color_b": [0.9, 0.9, 0.9]}},
        "ball": {"ka": 0.1, "kd": 0.7, "ks": 0.4, "shininess": 30,
                 "texture": {"type": "checker", "size": 0.25}},
        "paint": {"ka": 0.3, "kd": 0.7, "ks": 0.3, "shininess": 20}
      },
      "lights": [{"type": "spot", "position": [1, 5, 3], "direction": [-0.2, -1, -0.6],
                  "inner_angle": 25, "outer_angle": 35, "intensity": [30, 30, 30]},
                 {"type": "point", "position": [-3, 4, 2], "intensity": [10, 9, 8]}],
      "objects": [
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
        {"type": "sphere", "center": [1.3, 0.7, 0], "radius": 0.7, "material": "ball"},
        {"type": "mesh", "file": ")" +
                        std::string(HIKARI_SOURCE_DIR) + R"(/scenes/models/vertex-colours.obj",
         "material": "paint", "transform": [{"translate": [-1.2, 1, 0]}]}
      ]})");
    return scene;
}

/// The kernels on the CPU and render_zbuffer agree on every pixel of `scene`: colours within
/// 1e-5, ids, depths and normals exactly.
void expect_kernels_match(const Scene& scene, ShadowMode shadows,
                          Interpolation interp = Interpolation::phong) {
    RasterSettings raster;
    raster.shadows = shadows;
    raster.interp = interp;
    raster.shadow_map_size = 512;
    const Framebuffer reference = render_zbuffer(scene, Film(scene.camera), {}, raster);
    const Framebuffer kernels =
        render_zbuffer_kernels(scene, Film(scene.camera), {}, raster, ExecutionDevice::cpu);
    const testing::KernelDifferences d = testing::compare_kernel_render(kernels, reference, 1e-5f);
    EXPECT_EQ(d.colour, 0u) << "largest difference " << d.largest;
    EXPECT_EQ(d.id, 0u);
    EXPECT_EQ(d.depth, 0u);
    EXPECT_EQ(d.normal, 0u);
    // Something was drawn, lit and shadowed: not a test of two blank images.
    EXPECT_GT(std::count_if(reference.id.begin(), reference.id.end(),
                            [](uint32_t id) { return id != k_background_id; }),
              static_cast<long>(reference.id.size() / 10));
}

/// The screen triangles of `scene`'s vertex stage (render_zbuffer's).
ProjectedScene projected(const Scene& scene) {
    return project_scene(scene, RasterSettings{}, SphereGeometry::exact);
}

TEST(ZBufferKernels, VertexStageGivesTheCpuScreenTrianglesBitForBit) {
    // Clipped floors (their pieces in their triangle's place), a mesh inside the view, culling.
    for (const bool cull : {false, true})
        for (const Scene& scene :
             {scene_file("bunny.json", 160, 120), scene_file("teapot.json", 131, 77),
              checker_and_vertex_colours(90, 60)}) {
            RasterSettings raster;
            raster.cull_back_faces = cull;
            const ProjectedScene cpu = project_scene(scene, raster, SphereGeometry::exact);
            const ProjectedScene kernels =
                project_scene_with_kernels(scene, raster, ExecutionDevice::cpu);
            ASSERT_EQ(kernels.triangles.size(), cpu.triangles.size());
            EXPECT_EQ(std::memcmp(kernels.triangles.data(), cpu.triangles.data(),
                                  cpu.triangles.size() * sizeof(ScreenTriangle)),
                      0);
            EXPECT_EQ(kernels.clip_positions, cpu.clip_positions);
            EXPECT_EQ(kernels.counts.culled, cpu.counts.culled);
            EXPECT_EQ(kernels.counts.cut, cpu.counts.cut);
            EXPECT_EQ(kernels.counts.clipped_away, cpu.counts.clipped_away);
            EXPECT_GT(cpu.counts.cut + cpu.counts.culled, 0u);
        }
}

TEST(ZBufferKernels, DepthTestGivesTheCpuBuffersBitForBit) {
    // The rasterizer alone: every pixel's nearest screen triangle and depth 1 / inv_w, for a
    // dense mesh (ties on shared edges, the top-left rule) and for clipped floors.
    for (const Scene& scene :
         {scene_file("bunny.json", 160, 120), scene_file("teapot.json", 131, 77),
          scene_file("assignment.json", 96, 72), checker_and_vertex_colours(90, 60)}) {
        const ProjectedScene ps = projected(scene);
        const int w = scene.camera.width, h = scene.camera.height;
        const size_t pixels = static_cast<size_t>(w) * h;
        std::vector<uint32_t> nearest(pixels), kernel_nearest(pixels);
        std::vector<float> depth(pixels), kernel_depth(pixels);
        ZBufferWorkspace ws;
        zbuffer_draw(ps.triangles, w, h, ws, nearest.data(), depth.data());
        zbuffer_kernels_draw(ps.triangles, w, h, kernel_nearest.data(), kernel_depth.data(),
                             ExecutionDevice::cpu);
        EXPECT_EQ(kernel_nearest, nearest);
        size_t differing = 0;
        for (size_t i = 0; i < pixels; ++i)
            differing +=
                std::bit_cast<uint32_t>(kernel_depth[i]) != std::bit_cast<uint32_t>(depth[i]);
        EXPECT_EQ(differing, 0u);
    }
}

TEST(ZBufferKernels, EqualDepthsKeepTheEarlierTriangleAsTheCpuDoes) {
    // Two copies of one triangle: every pixel sees the first, as Alg 4.2's z < Z keeps it.
    ScreenTriangle t{
        {ScreenVertex{{2.3f, 1.1f, -0.5f}, 0.5f}, ScreenVertex{{30.7f, 4.2f, -0.5f}, 0.5f},
         ScreenVertex{{9.9f, 28.4f, -0.5f}, 0.5f}},
        0};
    std::vector<ScreenTriangle> triangles{t, t};
    triangles[1].source = 1;
    std::vector<uint32_t> nearest(32 * 32);
    zbuffer_kernels_draw(triangles, 32, 32, nearest.data(), nullptr, ExecutionDevice::cpu);
    EXPECT_GT(std::count(nearest.begin(), nearest.end(), 0u), 100);
    EXPECT_EQ(std::count(nearest.begin(), nearest.end(), 1u), 0);
}

TEST(ZBufferKernels, AssignmentSceneMatchesTheCpuZBuffer) {
    // The exact sphere (the ray tracer's hit per pixel), and the sphere as polygons.
    expect_kernels_match(scene_file("assignment.json", 96, 72), ShadowMode::map);
    expect_kernels_match(scene_file("assignment.json", 96, 72, 48), ShadowMode::map);
    expect_kernels_match(scene_file("assignment-3-specular.json", 64, 48), ShadowMode::none);
}

TEST(ZBufferKernels, ExactSpheresMatchTheCpuZBuffer) {
    // Spheres in front of and behind triangles, casting shadows, under a checker (sphere uv).
    expect_kernels_match(scene_file("shadows.json", 128, 72), ShadowMode::map);
    expect_kernels_match(checker_and_vertex_colours(120, 80), ShadowMode::pcf);
}

TEST(ZBufferKernels, MeshesMatchTheCpuZBuffer) {
    expect_kernels_match(scene_file("teapot.json", 120, 90), ShadowMode::none);
    expect_kernels_match(scene_file("bunny.json", 160, 120), ShadowMode::none);
}

TEST(ZBufferKernels, CheckerTexturesAndVertexColoursMatchTheCpuZBuffer) {
    Scene polygons = checker_and_vertex_colours(120, 80);
    for (Sphere& s : polygons.spheres) s.segments = 40;
    expect_kernels_match(polygons, ShadowMode::none);
}

TEST(ZBufferKernels, ShadowMapsMatchTheCpuZBuffer) {
    // The bunny of B4 (a cube map around its point light, a directional map), the shadow scene,
    // spot lights' cone maps; map, pcf and pcss lookups.
    expect_kernels_match(scene_file("bunny.json", 160, 120), ShadowMode::map);
    expect_kernels_match(scene_file("shadows.json", 128, 72, 40), ShadowMode::map);
    expect_kernels_match(scene_file("shadows.json", 128, 72, 40), ShadowMode::pcf);
    expect_kernels_match(scene_file("light-spot.json", 100, 75), ShadowMode::map);
    // PCSS of point-sized lights is PCF (no penumbra to search for), through the same code.
    expect_kernels_match(scene_file("light-spot.json", 100, 75), ShadowMode::pcss);
}

TEST(ZBufferKernels, FlatAndGouraudShadingMatchTheCpuZBuffer) {
    // Spheres become polygons; shadows are asked at the pixel, colours at the centroid or corners.
    for (const Interpolation interp : {Interpolation::flat, Interpolation::gouraud}) {
        expect_kernels_match(scene_file("shadows.json", 128, 72), ShadowMode::map, interp);
        expect_kernels_match(checker_and_vertex_colours(90, 60), ShadowMode::none, interp);
    }
}

TEST(ZBufferKernels, SameImageForAnyThreadCount) {
    const Scene scene = scene_file("bunny.json", 96, 72);
    RasterSettings raster;
    raster.shadows = ShadowMode::map;
    raster.shadow_map_size = 256;
    Framebuffer one, two;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = render_zbuffer_kernels(scene, Film(scene.camera), {}, raster, ExecutionDevice::cpu);
    }
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        two = render_zbuffer_kernels(scene, Film(scene.camera), {}, raster, ExecutionDevice::cpu);
    }
    EXPECT_EQ(one.film.linear().pixels, two.film.linear().pixels);
    EXPECT_EQ(one.id, two.id);
}

TEST(ZBufferKernels, ScenesTheKernelsLackAreRefusedByName) {
    const Scene bunny = scene_file("bunny.json", 8, 8);
    EXPECT_EQ(zbuffer_kernel_refusal(bunny, {}), "");
    Scene area = bunny;
    area.lights.push_back(AreaLight{{0, 4, 0}, {1, 0, 0}, {0, 0, 1}, {1, 1, 1}});
    EXPECT_NE(zbuffer_kernel_refusal(area, {}).find("area lights"), std::string::npos);
    EXPECT_THROW(render_zbuffer_kernels(area, Film(area.camera), {}, {}, ExecutionDevice::cpu),
                 InputError);
    Scene textured = bunny;
    textured.materials[0].texture = ImageTexture{};
    EXPECT_NE(zbuffer_kernel_refusal(textured, {}).find("image textures"), std::string::npos);
    textured.materials[0].texture = CheckerTexture{};
    EXPECT_EQ(zbuffer_kernel_refusal(textured, {}), "");
    Scene environment = bunny;
    environment.lights.push_back(EnvironmentLight{});
    EXPECT_NE(zbuffer_kernel_refusal(environment, {}).find("environment lights"),
              std::string::npos);
    RasterSettings volume;
    volume.shadows = ShadowMode::volume;
    EXPECT_NE(zbuffer_kernel_refusal(bunny, volume).find("--shadows volume"), std::string::npos);
}

// The GPU test (scripts/gpu-check.sh runs it on a GPU machine; skipped without a device): the
// same kernels as CUDA grids give the CPU run's ids and depths exactly (integer edge functions,
// IEEE division, no FMA), and its colours within the GPU's rounding of sqrt, pow and cos.
TEST(ZBufferKernels, CudaGridMatchesTheCpuRun) {
    if (!find_cuda_devices().problem.empty()) GTEST_SKIP() << find_cuda_devices().problem;
    RasterSettings raster;
    raster.shadows = ShadowMode::map;
    for (const Scene& scene :
         {scene_file("bunny.json", 320, 240), scene_file("teapot.json", 120, 90),
          checker_and_vertex_colours(160, 90)}) {
        const Framebuffer cpu =
            render_zbuffer_kernels(scene, Film(scene.camera), {}, raster, ExecutionDevice::cpu);
        const Framebuffer gpu =
            render_zbuffer_kernels(scene, Film(scene.camera), {}, raster, ExecutionDevice::cuda);
        const testing::KernelDifferences d = testing::compare_kernel_render(gpu, cpu, 1e-3f);
        EXPECT_EQ(d.colour, 0u) << "largest difference " << d.largest;
        EXPECT_EQ(d.id, 0u);
    }
}

TEST(ZBufferKernels, CudaWithoutADeviceSaysSoInOneLine) {
    const Scene scene = scene_file("bunny.json", 8, 8);
    testing::expect_no_device_in_one_line(
        [&] { render_zbuffer_kernels(scene, Film(scene.camera), {}, {}, ExecutionDevice::cuda); });
}

}  // namespace
}  // namespace hikari
