#pragma once
// The scanline method (the lecture's Algorithm 4.1, スキャンライン法): hidden-surface removal one
// scanline at a time, from an edge table and an active edge list, without a per-pixel depth buffer.

#include <span>

#include "hikari/frame/film.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/frame/render_settings.h"
#include "hikari/raster/raster_settings.h"
#include "hikari/raster/screen_triangle.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// Visible triangle at every pixel centre of a width × height image, by Algorithm 4.1: walk the
/// scanlines top to bottom, intersect the scan plane with every triangle (scan segments), sort the
/// segment end points by x, and in each sample span between consecutive end points keep the segment
/// of smallest depth, splitting the span where two segments cross in depth (interpenetration).
/// Coverage follows the top-left rule at pixel centres (raster/polygon_fill.h); zero-area and
/// non-finite triangles are ignored; nothing is culled. Deterministic for any thread count.
VisibilityBuffer scanline_visibility(std::span<const ScreenTriangle> triangles, int width,
                                     int height);

/// The `scanline` method: vertex stage (raster/vertex_pipeline.h), scanline_visibility, then the
/// shared deferred shading pass (raster/shade_visibility.h).
Framebuffer render_scanline(const Scene& scene, Film film, const RenderSettings& settings = {},
                            const RasterSettings& raster = {});

}  // namespace hikari
