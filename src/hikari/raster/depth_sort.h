#pragma once
// The depth sort (奥行きソート法, the lecture's Fig 4.6-4.9): painter's algorithms that paint
// polygons back to front, later paints covering earlier ones.

#include <span>

#include "hikari/frame/film.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/frame/render_settings.h"
#include "hikari/raster/raster_settings.h"
#include "hikari/raster/screen_triangle.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// Visible triangle at every pixel centre by the depth sort done properly (Newell, Newell & Sancha
/// 1972): sort by farthest depth, order overlapping pairs by the extent, plane-side and projection
/// tests, and split polygons by each other's planes where the order is cyclic (Fig 4.9a) or they
/// interpenetrate (Fig 4.9b); then paint back to front. Every piece keeps its ScreenTriangle index.
/// Coverage follows the top-left rule at pixel centres (raster/polygon_fill.h); zero-area and
/// non-finite triangles are ignored; nothing is culled. Deterministic.
VisibilityBuffer depth_sort_visibility(std::span<const ScreenTriangle> triangles, int width,
                                       int height);

/// The naive depth sort of Fig 4.7: order whole triangles by the depth of their centroids and paint
/// back to front, with no overlap tests and no splitting. Wrong wherever that order is (Fig 4.7,
/// cyclic overlap Fig 4.9a, interpenetration Fig 4.9b); kept to show those failures.
VisibilityBuffer depth_sort_naive_visibility(std::span<const ScreenTriangle> triangles, int width,
                                             int height);

/// The `depthsort` method: vertex stage, depth_sort_visibility, shared shading pass.
Framebuffer render_depth_sort(const Scene& scene, Film film, const RenderSettings& settings = {},
                              const RasterSettings& raster = {});

/// The `depthsort-naive` method: vertex stage, depth_sort_naive_visibility, shared shading pass.
Framebuffer render_depth_sort_naive(const Scene& scene, Film film,
                                    const RenderSettings& settings = {},
                                    const RasterSettings& raster = {});

}  // namespace hikari
