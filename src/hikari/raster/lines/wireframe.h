#pragma once
// The wireframe method (the lecture's Fig 4.1a): every edge of every face, seen through the
// model, with no hidden-surface removal.

#include <span>

#include "hikari/core/image.h"
#include "hikari/frame/film.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/frame/line_drawing.h"
#include "hikari/frame/render_settings.h"
#include "hikari/raster/lines/line_settings.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// Every model edge of `scene` (raster/model_edges.h: the model's own, each once; spheres and
/// planes tessellated as the raster methods do), clipped to the view. With
/// lines.cull_back_faces, edges whose faces all face away are left out.
LineDrawing draw_wireframe(const Scene& scene, const LineSettings& lines);

/// `image` (linear colour, the camera's size) with `scene`'s wireframe drawn over it in `colour`
/// (`--wireframe-overlay`): the triangles a raster method drew, as the lines of draw_wireframe,
/// composited over the picture as rasterize_lines composites them over a background. Where
/// `depth` (the picture's depth AOV, eye distances) is not empty, each line shows only where it is
/// not behind the surface the pixel sees (within k_overlay_depth_tolerance), tested segment by
/// segment: the visible edges, whichever hidden edges share their pixels.
void overlay_wireframe(const Scene& scene, const LineSettings& lines, Vec3 colour,
                       std::span<const float> depth, Image& image);

/// A line on the surface a pixel sees may lie this fraction of its depth behind it (the pixel
/// centre sees a neighbouring triangle, or the line's pixel is not its own centre).
inline constexpr float k_overlay_depth_tolerance = 0.01f;

/// The `wireframe` method: draw_wireframe rasterized with anti-aliasing (raster/line_raster.h).
Framebuffer render_wireframe(const Scene& scene, Film film, const RenderSettings& settings,
                             const LineSettings& lines);

}  // namespace hikari
