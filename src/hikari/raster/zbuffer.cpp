#include "hikari/raster/zbuffer.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <memory>
#include <mutex>
#include <vector>

#include "hikari/core/build_cache.h"
#include "hikari/core/cancel.h"
#include "hikari/core/parallel.h"
#include "hikari/core/ray.h"
#include "hikari/frame/tiles.h"
#include "hikari/raster/half_space.h"
#include "hikari/raster/shade_visibility.h"
#include "hikari/raster/tile_bins.h"
#include "hikari/raster/vertex_pipeline.h"
#include "hikari/raster/zbuffer_tile.h"

namespace hikari {

namespace {

/// The render's observer: told nothing, costs nothing.
struct NoFragmentObserver {
    static constexpr bool k_active = false;
    void fragment(int, int, uint32_t, float, float, bool) const {}
    uint32_t* sphere_fragment_counts() const { return nullptr; }
};

/// Records the fragments of one pixel (explain).
struct PixelFragments {
    static constexpr bool k_active = true;
    int x, y;
    std::vector<ZBufferFragment>& out;
    void fragment(int px, int py, uint32_t t, float z, float stored, bool won) const {
        if (px == x && py == y) out.push_back({t, z, stored, won});
    }
    uint32_t* sphere_fragment_counts() const { return nullptr; }  // explain draws no exact sphere
};

/// Counts every pixel's fragments (each pixel belongs to one tile: no two threads share a count).
struct FragmentCounts {
    static constexpr bool k_active = true;
    int width;
    uint32_t* count;
    void fragment(int x, int y, uint32_t, float, float, bool) const {
        ++count[static_cast<size_t>(y) * width + x];
    }
    uint32_t* sphere_fragment_counts() const { return count; }
};

/// The workspace a render session keeps for its Z-buffer renders (a BuildCache entry depends on
/// no scene part: it holds no result, only room). The render that holds the lock uses it.
struct KeptZBufferWorkspace {
    std::unique_ptr<std::mutex> lock = std::make_unique<std::mutex>();
    std::unique_ptr<ZBufferWorkspace> workspace = std::make_unique<ZBufferWorkspace>();
};

/// Counts exact spheres' fragments per pixel and nothing else: triangles take the SIMD kernel,
/// which counts its own.
struct SphereFragments {
    static constexpr bool k_active = false;
    FragmentCounts counts;
    void fragment(int, int, uint32_t, float, float, bool) const {}
    uint32_t* sphere_fragment_counts() const { return counts.count; }
};

/// The whole-frame half of Alg 4.2 that precedes the tiles: each triangle's edge functions
/// and depth plane, and the tiles it is binned to (in triangle order).
template <class Triangles>
void zbuffer_setup(const Triangles& triangles, int width, int height, ZBufferWorkspace& ws) {
    ws.setup.resize(triangles.size());
    ws.home.resize(triangles.size());
    hikari::parallel_for(tbb::blocked_range<size_t>(0, triangles.size(), 1024),
                         [&](const tbb::blocked_range<size_t>& range) {
                             throw_if_cancelled();  // SIGINT, Ctrl-C in Python
                             for (size_t i = range.begin(); i != range.end(); ++i)
                                 ws.home[i] =
                                     setup_half_space(triangles[i], width, height, ws.setup[i])
                                         ? home_tile(ws.setup[i], width)
                                         : k_no_tile;
                         });
    bin_triangles(ws.setup, ws.home, width, height, ws.bins);
}

/// Alg 4.2 over one tile into its own `depth` and `nearest` (k_tile_size wide, from the tile's
/// corner; nearest may be null without spheres): Z = ∞ everywhere, then the tile's triangles
/// in order, then the exact spheres. The render's pass runs the SIMD tile kernel; an observer
/// that must see every fragment gets the per-pixel loop, which computes the same buffer.
/// Returns the fragments the kernel depth-tested (0 under an observer, which counts its own).
template <class Observer>
uint64_t zbuffer_tile(const ZBufferWorkspace& ws, const Tile& tile, ZBufferTileKernel* kernel,
                      float* depth, uint32_t* nearest, const Observer& observer,
                      const SphereRaster* spheres, int width) {
    constexpr size_t k_pixels = size_t{k_tile_size} * k_tile_size;
    // Alg 4.2: Z(i, j) = ∞ for every pixel of the tile.
    std::fill_n(depth, k_pixels, k_infinity);
    if (nearest) std::fill_n(nearest, k_pixels, k_no_triangle);
    const size_t tile_index = ws.bins.tile_at(tile.x0, tile.y0);
    uint64_t tested = 0;
    if constexpr (Observer::k_active) {
        ws.bins.for_each(tile_index, [&](uint32_t t) {
            const HalfSpaceTriangle& h = ws.setup[t];
            for_each_covered_pixel(h, tile.x0, tile.y0, tile.x1, tile.y1,
                                   [&](int x, int y, float b0, float b1, float b2) {
                                       const float z = interpolated_depth(h, b0, b1, b2);
                                       const int i = (y - tile.y0) * k_tile_size + (x - tile.x0);
                                       observer.fragment(x, y, t, z, depth[i], z < depth[i]);
                                       // Alg 4.2: the depth test; nearer fragments replace.
                                       if (z < depth[i]) {
                                           depth[i] = z;
                                           nearest[i] = t;
                                       }
                                   });
        });
    } else {
        TileDepth target{&tile, depth, nearest, k_infinity};
        ws.bins.for_each_run(tile_index, [&](const uint32_t* run, size_t count) {
            kernel(ws.setup.data(), run, count, target);
        });
        tested = target.tested;
    }
    if (spheres)
        draw_spheres_in_tile(*spheres, tile, depth, nearest, observer.sphere_fragment_counts(),
                             width);
    return tested;
}

/// Alg 4.2 over every tile of the image, into `nearest_out` and `depth_out` (row-major, either
/// may be null).
template <class Triangles, class Observer>
void zbuffer_pass(const Triangles& triangles, int width, int height, ZBufferWorkspace& ws,
                  uint32_t* nearest_out, float* depth_out, RenderControl* control,
                  const Observer& observer, const SphereRaster* spheres, SimdLevel level) {
    zbuffer_setup(triangles, width, height, ws);
    ZBufferTileKernel* const kernel = zbuffer_tile_kernel(level);
    for_each_tile(width, height, control, [&](const Tile& tile) {
        std::array<float, k_tile_size * k_tile_size> depth;
        std::array<uint32_t, k_tile_size * k_tile_size> nearest;
        zbuffer_tile(ws, tile, kernel, depth.data(),
                     nearest_out || spheres || Observer::k_active ? nearest.data() : nullptr,
                     observer, spheres, width);
        for (int y = tile.y0; y < tile.y1; ++y) {
            const size_t row = static_cast<size_t>(y) * width + tile.x0;
            const size_t local = static_cast<size_t>(y - tile.y0) * k_tile_size;
            const auto columns = static_cast<size_t>(tile.x1 - tile.x0);
            if (nearest_out) std::copy_n(nearest.data() + local, columns, nearest_out + row);
            if (depth_out) std::copy_n(depth.data() + local, columns, depth_out + row);
        }
    });
}

/// zbuffer_pass into a new visibility buffer.
template <class Observer>
VisibilityBuffer zbuffer_pass(std::span<const ScreenTriangle> triangles, int width, int height,
                              RenderControl* control, const Observer& observer,
                              const SphereRaster* spheres = nullptr) {
    VisibilityBuffer vis{width, height,
                         std::vector<uint32_t>(static_cast<size_t>(width) * height, k_no_triangle)};
    ZBufferWorkspace ws;
    zbuffer_pass(triangles, width, height, ws, vis.triangle.data(), nullptr, control, observer,
                 spheres, best_simd_level());
    return vis;
}

}  // namespace

void zbuffer_draw(std::span<const ScreenTriangle> triangles, int width, int height,
                  ZBufferWorkspace& workspace, uint32_t* nearest, float* depth,
                  RenderControl* control, SimdLevel level) {
    zbuffer_pass(triangles, width, height, workspace, nearest, depth, control, NoFragmentObserver{},
                 nullptr, level);
}

void zbuffer_draw(const IndexedScreenTriangles& triangles, int width, int height,
                  ZBufferWorkspace& workspace, uint32_t* nearest, float* depth,
                  RenderControl* control, SimdLevel level) {
    zbuffer_pass(triangles, width, height, workspace, nearest, depth, control, NoFragmentObserver{},
                 nullptr, level);
}

VisibilityBuffer zbuffer_visibility(std::span<const ScreenTriangle> triangles, int width,
                                    int height, RenderControl* control,
                                    const SphereRaster* spheres) {
    return zbuffer_pass(triangles, width, height, control, NoFragmentObserver{}, spheres);
}

VisibilityBuffer zbuffer_visibility_counted(std::span<const ScreenTriangle> triangles, int width,
                                            int height, std::vector<uint32_t>& fragments_per_pixel,
                                            const SphereRaster* spheres) {
    fragments_per_pixel.assign(static_cast<size_t>(width) * height, 0);
    return zbuffer_pass(triangles, width, height, nullptr,
                        FragmentCounts{width, fragments_per_pixel.data()}, spheres);
}

VisibilityBuffer zbuffer_visibility_at(std::span<const ScreenTriangle> triangles, int width,
                                       int height, int x, int y,
                                       std::vector<ZBufferFragment>& fragments) {
    return zbuffer_pass(triangles, width, height, nullptr, PixelFragments{x, y, fragments});
}

Framebuffer render_zbuffer(const Scene& scene, Film film, const RenderSettings& settings,
                           const RasterSettings& raster) {
    // Per-pixel shading can use the exact sphere; flat and Gouraud shading need its polygons.
    const SphereGeometry geometry =
        raster.interp == Interpolation::phong ? SphereGeometry::exact : SphereGeometry::tessellated;
    const ProjectedScene ps = project_scene(scene, raster, geometry);
    const int width = scene.camera.width, height = scene.camera.height;
    const SphereRaster spheres =
        prepare_sphere_raster(ps.scene.spheres, ps.view, camera_pixel_rays(scene.camera, ps.view),
                              static_cast<uint32_t>(ps.triangles.size()));
    const bool any_spheres = !spheres.spheres.empty();
    if (settings.stats) {
        add_vertex_stage_stats(ps, *settings.stats);
        settings.stats->raster_exact_spheres += spheres.spheres.size();
    }
    if (raster.shadows == ShadowMode::volume && !scene.lights.empty()) {
        // The stencils count against every pixel's depth: visibility first, then shading.
        VisibilityBuffer vis;
        if (!settings.stats) {
            vis = zbuffer_visibility(ps.triangles, width, height, settings.control,
                                     any_spheres ? &spheres : nullptr);
        } else {
            std::vector<uint32_t> fragments;
            vis = zbuffer_visibility_counted(ps.triangles, width, height, fragments,
                                             any_spheres ? &spheres : nullptr);
            uint64_t total = 0;
            for (const uint32_t f : fragments) total += f;
            settings.stats->raster_fragments += total;
            settings.stats->raster_covered_pixels +=
                static_cast<uint64_t>(std::count_if(vis.triangle.begin(), vis.triangle.end(),
                                                    [](uint32_t t) { return t != k_no_triangle; }));
        }
        return shade_visibility(scene, ps, vis, std::move(film), settings, raster);
    }
    // Alg 4.2 tile by tile, each tile shaded as soon as its Z-buffer is done. A session keeps
    // the workspace, so that its next render allocates none (unless two renders overlap).
    ZBufferWorkspace local;
    const std::shared_ptr<const KeptZBufferWorkspace> kept = cached_or_built<KeptZBufferWorkspace>(
        settings.cache, &scene, "zbuffer workspace", SceneParts::none,
        [] { return KeptZBufferWorkspace{}; });
    const std::unique_lock hold(*kept->lock, std::try_to_lock);
    ZBufferWorkspace& ws = hold.owns_lock() ? *kept->workspace : local;
    zbuffer_setup(std::span<const ScreenTriangle>(ps.triangles), width, height, ws);
    ZBufferTileKernel* const kernel = zbuffer_tile_kernel(raster.simd);
    // Exact spheres' fragments are counted per pixel (draw_spheres_in_tile), triangles' by the
    // kernel.
    std::vector<uint32_t> sphere_fragments;
    if (settings.stats && any_spheres)
        sphere_fragments.assign(static_cast<size_t>(width) * height, 0);
    std::atomic<uint64_t> tested{0};
    const FragmentCounts sphere_counts{width, sphere_fragments.data()};
    Framebuffer fb = shade_tiles(
        scene, ps, std::move(film), settings, raster, [&](const Tile& tile, uint32_t* seen) {
            std::array<float, k_tile_size * k_tile_size> depth;
            uint64_t n = 0;
            if (sphere_fragments.empty())
                n = zbuffer_tile(ws, tile, kernel, depth.data(), seen, NoFragmentObserver{},
                                 any_spheres ? &spheres : nullptr, width);
            else
                n = zbuffer_tile(ws, tile, kernel, depth.data(), seen,
                                 SphereFragments{sphere_counts}, &spheres, width);
            if (settings.stats) tested.fetch_add(n, std::memory_order_relaxed);
        });
    if (settings.stats) {
        uint64_t total = tested.load();
        for (const uint32_t f : sphere_fragments) total += f;
        settings.stats->raster_fragments += total;
    }
    return fb;
}

}  // namespace hikari
