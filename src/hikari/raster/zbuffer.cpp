#include "hikari/raster/zbuffer.h"

#include <vector>

#include "hikari/core/parallel.h"
#include "hikari/core/ray.h"
#include "hikari/frame/tiles.h"
#include "hikari/raster/half_space.h"
#include "hikari/raster/shade_visibility.h"
#include "hikari/raster/tile_bins.h"
#include "hikari/raster/vertex_pipeline.h"

namespace hikari {

namespace {

/// The render's observer: told nothing, costs nothing.
struct NoFragmentObserver {
    static constexpr bool k_active = false;
    void fragment(int, int, uint32_t, float, float, bool) const {}
};

/// Records the fragments of one pixel (explain).
struct PixelFragments {
    static constexpr bool k_active = true;
    int x, y;
    std::vector<ZBufferFragment>& out;
    void fragment(int px, int py, uint32_t t, float z, float stored, bool won) const {
        if (px == x && py == y) out.push_back({t, z, stored, won});
    }
};

/// Counts every pixel's fragments (each pixel belongs to one tile: no two threads share a count).
struct FragmentCounts {
    static constexpr bool k_active = true;
    int width;
    uint32_t* count;
    void fragment(int x, int y, uint32_t, float, float, bool) const {
        ++count[static_cast<size_t>(y) * width + x];
    }
};

template <class Observer>
VisibilityBuffer zbuffer_pass(std::span<const ScreenTriangle> triangles, int width, int height,
                              RenderControl* control, const Observer& observer,
                              const SphereRaster* spheres = nullptr) {
    VisibilityBuffer vis{width, height,
                         std::vector<uint32_t>(static_cast<size_t>(width) * height, k_no_triangle)};
    std::vector<HalfSpaceTriangle> setup(triangles.size());
    std::vector<uint8_t> valid(triangles.size());
    hikari::parallel_for(size_t{0}, triangles.size(), [&](size_t i) {
        valid[i] = setup_half_space(triangles[i], width, height, setup[i]) ? 1 : 0;
    });
    const TileBins bins = bin_triangles(setup, valid, width, height);

    for_each_tile(width, height, control, [&](const Tile& tile) {
        // Alg 4.2: Z(i, j) = ∞ for every pixel of the tile.
        std::array<float, k_tile_size * k_tile_size> depth;
        std::array<uint32_t, k_tile_size * k_tile_size> nearest;
        depth.fill(k_infinity);
        nearest.fill(k_no_triangle);
        const size_t tile_index = bins.tile_at(tile.x0, tile.y0);
        for (uint32_t k = bins.begin[tile_index]; k < bins.begin[tile_index + 1]; ++k) {
            const uint32_t t = bins.triangle[k];
            const HalfSpaceTriangle& h = setup[t];
            for_each_covered_pixel(h, tile.x0, tile.y0, tile.x1, tile.y1,
                                   [&](int x, int y, float b0, float b1, float b2) {
                                       // 1/w is affine in screen space: interpolate it, invert.
                                       const float inv_w =
                                           b0 * h.inv_w[0] + b1 * h.inv_w[1] + b2 * h.inv_w[2];
                                       const float z = 1.0f / inv_w;
                                       const int i = (y - tile.y0) * k_tile_size + (x - tile.x0);
                                       if constexpr (Observer::k_active)
                                           observer.fragment(x, y, t, z, depth[i], z < depth[i]);
                                       // Alg 4.2: the depth test; nearer fragments replace.
                                       if (z < depth[i]) {
                                           depth[i] = z;
                                           nearest[i] = t;
                                       }
                                   });
        }
        if (spheres) draw_spheres_in_tile(*spheres, tile, depth.data(), nearest.data());
        for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x)
                vis.triangle[static_cast<size_t>(y) * width + x] =
                    nearest[(y - tile.y0) * k_tile_size + (x - tile.x0)];
    });
    return vis;
}

}  // namespace

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
    VisibilityBuffer vis;
    if (!settings.stats) {
        vis = zbuffer_visibility(ps.triangles, width, height, settings.control, &spheres);
    } else {
        std::vector<uint32_t> fragments;
        vis = zbuffer_visibility_counted(ps.triangles, width, height, fragments, &spheres);
        uint64_t total = 0;
        for (const uint32_t f : fragments) total += f;
        settings.stats->raster_fragments += total;
        report_raster_stats(ps, vis, *settings.stats);
    }
    return shade_visibility(scene, ps, vis, std::move(film), settings, raster);
}

}  // namespace hikari
