#pragma once
// Deferred shading shared by every raster method: once hidden-surface removal has decided which
// triangle each pixel centre sees, this pass interpolates that triangle's attributes and applies
// the lecture's one shading model (shading/phong.h, Fig 4.29).

#include <functional>
#include <span>
#include <utility>

#include "hikari/frame/film.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/frame/render_settings.h"
#include "hikari/frame/tiles.h"
#include "hikari/raster/pixel_surface.h"
#include "hikari/raster/raster_settings.h"
#include "hikari/raster/screen_triangle.h"
#include "hikari/raster/vertex_pipeline.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// Perspective-correct barycentric weights of the point of triangle (c0, c1, c2), given in clip
/// space, that projects to NDC point (ndc_x, ndc_y). Uses 2D homogeneous coordinates (Olano &
/// Greer 1997): the weights are the inverse of [x; y; w] applied to (ndc_x, ndc_y, 1),
/// normalized to sum 1 — the same as interpolating attribute / w and 1 / w linearly in screen
/// space, but valid for any source triangle, clipped or not. Returns false for a triangle seen
/// edge-on.
bool perspective_barycentrics(Vec4 c0, Vec4 c1, Vec4 c2, double ndc_x, double ndc_y,
                              std::array<float, 3>& weights);

// PixelUv and perspective_uv: raster/pixel_surface.h (shared with the GPU kernels).

/// Fills colour (into `film`, of the visibility buffer's size), depth (eye distance |p − eye|),
/// id (1 + PrimitiveId) and normal (unit, facing the eye) for every pixel whose centre
/// `visibility` names a triangle of `projected`; other pixels get the scene background (colour)
/// and "nothing seen" (AOVs). Colour is ambient + Lambert + Phong for every light, interpolated
/// as `raster.interp` says, with the shadows `raster.shadows` asks for (none, or shadow maps of
/// `raster.shadow_map_size`: raster/shadow_map.h); normals are turned toward the eye as the ray
/// tracer turns them, so both pipelines shade a surface alike. Parallel over tiles; reports to
/// `settings.control`. The AOV buffers are made and filled only when `settings.aov_buffers`.
/// Visibility values past the screen triangles name the exact spheres of `projected.scene`
/// (raster/sphere_raster.h): their pixels show the ray tracer's hit, shaded per pixel.
Framebuffer shade_visibility(const Scene& scene, const ProjectedScene& projected,
                             const VisibilityBuffer& visibility, Film film,
                             const RenderSettings& settings, const RasterSettings& raster);

/// A visibility method that decides one tile at a time: fills `seen`, the tile's k_tile_size ×
/// k_tile_size visibility values (VisibilityBuffer's) row-major from its top-left pixel,
/// k_tile_size wide whatever the tile's size. Called on many threads at once.
using TileVisibility = std::function<void(const Tile& tile, uint32_t* seen)>;

/// shade_visibility fused with a visibility method that works tile by tile: each tile is shaded
/// as soon as `visible` has decided it, while its values are in cache, and no visibility buffer
/// is made. For every shadow mode but volume (whose stencils need every pixel's depth first).
/// Adds the covered pixels to `settings.stats`. Triangle pixels are shaded in SIMD lanes
/// (raster/shade_lanes.h) when the interpolation is Phong and every light a delta light; the
/// colours are bit-identical to shading each pixel alone, and to shade_visibility's.
Framebuffer shade_tiles(const Scene& scene, const ProjectedScene& projected, Film film,
                        const RenderSettings& settings, const RasterSettings& raster,
                        const TileVisibility& visible);

/// Adds the vertex stage's counts to `stats`.
void add_vertex_stage_stats(const ProjectedScene& ps, RenderStats& stats);

/// Adds the vertex stage's counts and the pixels `vis` covers to `stats`.
void report_raster_stats(const ProjectedScene& ps, const VisibilityBuffer& vis, RenderStats& stats);

/// One raster method end to end (Fig 4.2): the shared vertex stage, the method's own hidden-surface
/// removal `visible(screen_triangles, width, height) -> VisibilityBuffer`, the shared shading pass.
template <class VisibilityFn>
Framebuffer render_raster(const Scene& scene, Film film, const RenderSettings& settings,
                          const RasterSettings& raster, VisibilityFn&& visible) {
    const ProjectedScene ps = project_scene(scene, raster);
    const VisibilityBuffer vis = visible(std::span<const ScreenTriangle>(ps.triangles),
                                         scene.camera.width, scene.camera.height);
    if (settings.stats) report_raster_stats(ps, vis, *settings.stats);
    return shade_visibility(scene, ps, vis, std::move(film), settings, raster);
}

}  // namespace hikari
