#include "hikari/raster/zbuffer_kernels.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <utility>
#include <variant>

#include <fmt/format.h>

#include "hikari/core/error.h"
#include "hikari/integrators/device_scene.h"
#include "hikari/raster/clip.h"
#include "hikari/raster/shade_visibility.h"
#include "hikari/raster/shadow_map.h"
#include "hikari/raster/sphere_raster.h"
#include "hikari/raster/tessellate.h"
#include "hikari/raster/vertex_pipeline.h"
#include "hikari/raster/zbuffer_kernel.h"
#include "hikari/shading/lights.h"

namespace hikari {

namespace {

template <class T>
FlatView<T> hold(DeviceArena& arena, const std::vector<T>& v) {
    return arena.hold(std::span<const T>(v.data(), v.size()));
}

/// The vertex stage's output, the arrays where the kernels wrote them.
struct DeviceProjection {
    RasterScene scene;  ///< the tessellated scene (host)
    RasterView view;
    Vec4* clip_positions = nullptr;  ///< per vertex of `scene`
    ScreenTriangle* triangles = nullptr;
    size_t triangle_count = 0;
    VertexStageCounts counts;
};

/// project_scene(scene, raster, SphereGeometry::exact) with kernels: each vertex transformed
/// and each triangle culled or kept whole on `arena`'s device; the few triangles that cross
/// the near plane or the guard band clipped on the host (project_to_screen's project_one), their
/// pieces in their triangle's place. The same screen triangles, in the same order.
DeviceProjection project_with_kernels(const Scene& scene, const RasterSettings& raster,
                                      DeviceArena& arena) {
    const ExecutionDevice device = arena.device();
    DeviceProjection out;
    // Per-pixel shading can use the exact sphere; flat and Gouraud shading need its polygons.
    out.scene = tessellate_scene(scene, raster.interp == Interpolation::phong
                                            ? SphereGeometry::exact
                                            : SphereGeometry::tessellated);
    out.view = make_raster_view(scene.camera, out.scene, raster.sample_offset);
    const TriangleSet& tris = out.scene.triangles;
    const size_t vertices = tris.positions.size(), n = tris.size();
    const FlatView<Vec3> positions = hold(arena, tris.positions);
    const FlatView<std::array<uint32_t, 3>> indices = hold(arena, tris.indices);
    /* (0a) the vertices */
    const VertexKernel vertex{out.view, positions.data, arena.output<Vec4>(vertices),
                              arena.output<uint8_t>(vertices),
                              arena.output<ScreenVertex>(vertices)};
    launch_zbuffer_kernel(device, vertices, vertex);
    out.clip_positions = vertex.clip;
    /* (0b) the triangles' fates */
    const TriangleFateKernel fates{out.view,     raster.cull_back_faces, positions.data,
                                   indices.data, vertex.inside,          arena.output<uint8_t>(n)};
    launch_zbuffer_kernel(device, n, fates);
    // The clipped triangles' pieces (host), then every triangle's place, in triangle order.
    std::vector<std::pair<uint32_t, std::vector<ScreenTriangle>>> clipped;
    uint32_t* first = arena.output<uint32_t>(n + 1);
    out.counts.triangles_in = n;
    const auto finite = [](Vec4 p) {
        return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
    };
    for (size_t t = 0; t < n; ++t) {
        uint32_t pieces = 0;
        if (fates.fate[t] == k_fate_kept) {
            pieces = 1;
        } else if (fates.fate[t] == k_fate_culled) {
            ++out.counts.culled;
        } else {
            const auto& idx = tris.indices[t];
            const Vec4 a = vertex.clip[idx[0]], b = vertex.clip[idx[1]], c = vertex.clip[idx[2]];
            const ClipPolygon poly =
                finite(a) && finite(b) && finite(c) ? clip_triangle(a, b, c) : ClipPolygon{};
            if (poly.count < 3) {
                ++out.counts.clipped_away;
            } else {
                ++out.counts.cut;
                std::array<ScreenVertex, k_max_clip_vertices> sv;
                for (int i = 0; i < poly.count; ++i) sv[i] = to_screen(out.view, poly.v[i]);
                std::vector<ScreenTriangle> fan;
                for (int i = 1; i + 1 < poly.count; ++i)
                    fan.push_back({{sv[0], sv[i], sv[i + 1]}, static_cast<uint32_t>(t)});
                pieces = static_cast<uint32_t>(fan.size());
                clipped.emplace_back(static_cast<uint32_t>(t), std::move(fan));
            }
        }
        first[t + 1] = first[t] + pieces;
    }
    /* (0c) the screen triangles */
    out.triangle_count = first[n];
    out.triangles = arena.output<ScreenTriangle>(out.triangle_count);
    launch_zbuffer_kernel(
        device, n,
        TriangleAssembleKernel{indices.data, fates.fate, first, vertex.screen, out.triangles});
    for (const auto& [t, fan] : clipped)
        std::copy(fan.begin(), fan.end(), out.triangles + first[t]);
    return out;
}

/// The Z-buffer's buffers for one image, where the kernels wrote them (arena memory).
struct DrawnBuffers {
    uint32_t* nearest = nullptr;
    float* depth = nullptr;
};

/// Steps (1) to (3) of zbuffer_kernel.h over `triangles` (already where the kernels read them):
/// setup, binning, the per-pixel depth test into arena buffers.
DrawnBuffers draw_with_kernels(const ScreenTriangle* triangles, size_t count, int width, int height,
                               bool want_depth, DeviceArena& arena,
                               const SphereRaster* spheres = nullptr) {
    const ExecutionDevice device = arena.device();
    const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
    const int tiles_x = (width + k_tile_size - 1) / k_tile_size;
    const int tiles_y = (height + k_tile_size - 1) / k_tile_size;
    const size_t tiles = static_cast<size_t>(tiles_x) * static_cast<size_t>(tiles_y);
    /* (1) setup */
    TriangleSetupKernel setup{triangles, width, height, arena.output<HalfSpaceTriangle>(count),
                              arena.output<uint8_t>(count)};
    launch_zbuffer_kernel(device, count, setup);
    /* (2) bins: counts per tile and chunk, places, lists in triangle order */
    const size_t chunks = (count + k_bin_chunk_triangles - 1) / k_bin_chunk_triangles;
    uint32_t* counts = arena.output<uint32_t>(tiles * chunks);
    uint32_t* totals = arena.output<uint32_t>(tiles);
    const BinChunks bins{setup.setup, setup.drawn, count, chunks, tiles_x};
    launch_zbuffer_kernel(device, chunks, BinCountKernel{bins, counts});
    launch_zbuffer_kernel(device, tiles, BinTotalKernel{chunks, counts, totals});
    // The tiles' starts: a prefix sum over a few thousand tiles, on the host.
    uint32_t* tile_begin = arena.output<uint32_t>(tiles + 1);
    for (size_t i = 0; i < tiles; ++i) tile_begin[i + 1] = tile_begin[i] + totals[i];
    uint32_t* list = arena.output<uint32_t>(tile_begin[tiles] > 0 ? tile_begin[tiles] : 1);
    launch_zbuffer_kernel(device, chunks, BinFillKernel{bins, counts, tile_begin, list});
    /* (3) the depth test */
    DrawnBuffers out{arena.output<uint32_t>(pixels),
                     want_depth ? arena.output<float>(pixels) : nullptr};
    ZBufferPixelKernel pixel{setup.setup, tile_begin, list, width, tiles_x, out.depth, out.nearest};
    if (spheres && !spheres->spheres.empty()) {
        if (spheres->tiles_x != tiles_x || spheres->tile_begin.size() != tiles + 1)
            throw std::logic_error("zbuffer kernels: the spheres' tiles are not the image's");
        pixel.spheres = arena.hold(spheres->spheres).data;
        pixel.sphere_count = spheres->spheres.size();
        pixel.sphere_bounds = hold(arena, spheres->bounds).data;
        pixel.sphere_tile_begin = hold(arena, spheres->tile_begin).data;
        pixel.tile_spheres = hold(arena, spheres->tile_spheres).data;
        pixel.frame = spheres->rays.frame;
        pixel.sample_offset = spheres->rays.sample_offset;
        pixel.clip_from_world = spheres->clip_from_world;
        pixel.orthographic = spheres->orthographic;
        pixel.first_sphere_id = spheres->first_id;
    }
    launch_zbuffer_kernel(device, pixels, pixel);
    return out;
}

/// The shadow maps where the kernels read them, and the faces they point to.
struct DeviceShadowMaps {
    std::vector<FlatShadowMap> maps;
    std::vector<std::vector<FlatShadowFace>> faces;
};

DeviceShadowMaps hold_shadow_maps(const ShadowMaps& maps, DeviceArena& arena) {
    DeviceShadowMaps out;
    out.faces.resize(maps.lights.size());
    for (size_t l = 0; l < maps.lights.size(); ++l) {
        FlatShadowMap flat;
        if (const auto& map = maps.lights[l]) {
            flat.present = true;
            flat.directional = map->directional;
            flat.cone = map->cone;
            flat.origin = map->origin;
            flat.direction = map->direction;
            flat.size = map->size;
            flat.texel_size = map->texel_size;
            for (const ShadowMapFace& face : map->faces)
                out.faces[l].push_back({face.view, arena.hold(std::span<const float>(
                                                       face.depth.data(), face.depth.size()))});
            flat.faces = hold(arena, out.faces[l]);
        }
        out.maps.push_back(flat);
    }
    return out;
}

}  // namespace

std::string zbuffer_kernel_refusal(const Scene& scene, const RasterSettings& raster) {
    if (std::string refusal = delta_lights_refusal(scene); !refusal.empty()) return refusal;
    if (std::string refusal = image_texture_refusal(scene); !refusal.empty()) return refusal;
    if (!scene.lights.empty() &&
        (raster.shadows == ShadowMode::volume || raster.shadows == ShadowMode::analytic))
        return fmt::format("--shadows {} is not in the kernels yet (map, pcf, pcss and none are)",
                           raster.shadows == ShadowMode::volume ? "volume" : "analytic");
    return {};
}

ProjectedScene project_scene_with_kernels(const Scene& scene, const RasterSettings& raster,
                                          ExecutionDevice device) {
    if (device == ExecutionDevice::cuda) require_cuda_device("--device cuda");
    DeviceArena arena(device);
    DeviceProjection dp = project_with_kernels(scene, raster, arena);
    ProjectedScene ps;
    ps.view = dp.view;
    ps.clip_positions.assign(dp.clip_positions,
                             dp.clip_positions + dp.scene.triangles.positions.size());
    ps.triangles.assign(dp.triangles, dp.triangles + dp.triangle_count);
    ps.counts = dp.counts;
    ps.scene = std::move(dp.scene);
    return ps;
}

void zbuffer_kernels_draw(std::span<const ScreenTriangle> triangles, int width, int height,
                          uint32_t* nearest, float* depth, ExecutionDevice device) {
    if (device == ExecutionDevice::cuda) require_cuda_device("--device cuda");
    DeviceArena arena(device);
    const FlatView<ScreenTriangle> held = arena.hold(triangles);
    const DrawnBuffers drawn =
        draw_with_kernels(held.data, held.count, width, height, depth != nullptr, arena);
    const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
    if (nearest) std::copy_n(drawn.nearest, pixels, nearest);
    if (depth) std::copy_n(drawn.depth, pixels, depth);
}

Framebuffer render_zbuffer_kernels(const Scene& scene, Film film, const RenderSettings& settings,
                                   const RasterSettings& raster, ExecutionDevice device) {
    if (device == ExecutionDevice::cuda) require_cuda_device("--device cuda");
    if (const std::string refusal = zbuffer_kernel_refusal(scene, raster); !refusal.empty())
        throw InputError(fmt::format("{} zbuffer: {}",
                                     device == ExecutionDevice::cuda ? "--device cuda" : "kernels",
                                     refusal));
    const int width = scene.camera.width, height = scene.camera.height;
    Framebuffer fb(std::move(film), width, height, settings.aov_buffers);
    DeviceArena arena(device);
    // The vertex stage, render_zbuffer's (exact spheres stay spheres, unprojected).
    const DeviceProjection ps = project_with_kernels(scene, raster, arena);
    if (settings.stats) {
        RenderStats& stats = *settings.stats;
        stats.raster_triangles += ps.counts.triangles_in;
        stats.raster_culled += ps.counts.culled;
        stats.raster_clipped_away += ps.counts.clipped_away;
        stats.raster_cut += ps.counts.cut;
        stats.raster_screen_triangles += ps.triangle_count;
    }
    const ShadowMode shadows = scene.lights.empty() ? ShadowMode::none : raster.shadows;
    std::shared_ptr<const ShadowMaps> maps;
    if (shadows != ShadowMode::none) {
        // Each face's depth keys drawn by the kernels (the CPU Z-buffer's buffer), turned into
        // the map's depths on the host; or the maps kept by the session (raster/shadow_map.h).
        const auto start = std::chrono::steady_clock::now();
        const FaceDepthDrawer drawer = [device](std::span<const ScreenTriangle> triangles, int w,
                                                int h, float* depth) {
            zbuffer_kernels_draw(triangles, w, h, nullptr, depth, device);
        };
        maps = shadow_maps_for_render(scene, ps.scene, raster.shadow_map_size, settings.cache,
                                      raster.shared_shadow_maps.get(), settings.stats, &drawer);
        if (settings.stats)
            settings.stats->shadow_pass_us += std::chrono::duration_cast<std::chrono::microseconds>(
                                                  std::chrono::steady_clock::now() - start)
                                                  .count();
    }

    // Exact spheres, drawn after each pixel's triangles (raster/sphere_raster.h).
    const SphereRaster spheres =
        prepare_sphere_raster(ps.scene.spheres, ps.view, camera_pixel_rays(scene.camera, ps.view),
                              static_cast<uint32_t>(ps.triangle_count));
    if (settings.stats) settings.stats->raster_exact_spheres += spheres.spheres.size();
    const DrawnBuffers drawn =
        draw_with_kernels(ps.triangles, ps.triangle_count, width, height, false, arena, &spheres);

    const TriangleSet& tris = ps.scene.triangles;
    const std::vector<Material> materials = device_materials(scene);
    std::vector<LightShadowView> views;
    for (const Light& light : scene.lights) views.push_back(shadow_view(light));
    const DeviceShadowMaps device_maps = maps ? hold_shadow_maps(*maps, arena) : DeviceShadowMaps{};
    ZBufferShadeKernel shade;
    shade.positions = hold(arena, tris.positions);
    shade.normals = hold(arena, tris.normals);
    shade.colors = hold(arena, tris.colors);
    shade.uvs = hold(arena, tris.uvs);
    shade.indices = hold(arena, tris.indices);
    shade.material = hold(arena, tris.material);
    shade.id = hold(arena, tris.id);
    shade.clip_positions = {ps.clip_positions, tris.positions.size()};
    shade.triangles = ps.triangles;
    shade.triangle_count = ps.triangle_count;
    shade.spheres = hold(arena, ps.scene.spheres).data;
    shade.sample_offset = ps.view.sample_offset;
    shade.nearest = drawn.nearest;
    shade.materials = hold(arena, materials).data;
    shade.lighting = {hold(arena, scene.lights).data, scene.lights.size(), scene.ambient};
    shade.background = scene.background;
    shade.frame = make_camera_frame(scene.camera);
    shade.width = width;
    shade.interp = raster.interp;
    shade.height = height;
    shade.shadows = shadows;
    shade.light_views = hold(arena, views).data;
    shade.maps = hold(arena, device_maps.maps).data;
    shade.planes = hold(arena, scene.planes).data;
    shade.plane_count = scene.planes.size();
    const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
    shade.colours = arena.output<Vec3>(pixels);
    if (settings.aov_buffers) {
        shade.depth = arena.output<float>(pixels);
        shade.ids = arena.output<uint32_t>(pixels);
        shade.normal = arena.output<Vec3>(pixels);
    }
    launch_zbuffer_kernel(device, pixels, shade);

    fb.set_colors(0, shade.colours, pixels);
    uint64_t covered = 0;
    for (size_t i = 0; i < pixels; ++i) {
        if (drawn.nearest[i] == k_no_triangle) continue;
        ++covered;
        if (!settings.aov_buffers) continue;
        fb.depth[i] = shade.depth[i];
        fb.id[i] = shade.ids[i];
        fb.normal[i] = shade.normal[i];
    }
    if (settings.stats) settings.stats->raster_covered_pixels += covered;
    if (settings.control) {
        settings.control->work_total = 1;
        settings.control->work_done = 1;
    }
    return fb;
}

}  // namespace hikari
