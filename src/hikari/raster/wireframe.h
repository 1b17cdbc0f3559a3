#pragma once
// The wireframe method (the lecture's Fig 4.1a): every edge of every face, seen through the
// model, with no hidden-surface removal.

#include "hikari/frame/film.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/frame/line_drawing.h"
#include "hikari/frame/render_settings.h"
#include "hikari/raster/line_settings.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// Every model edge of `scene` (raster/model_edges.h: the model's own, each once; spheres and
/// planes tessellated as the raster methods do), clipped to the view. With
/// lines.cull_back_faces, edges whose faces all face away are left out.
LineDrawing draw_wireframe(const Scene& scene, const LineSettings& lines);

/// The `wireframe` method: draw_wireframe rasterized with anti-aliasing (raster/line_raster.h).
Framebuffer render_wireframe(const Scene& scene, Film film, const RenderSettings& settings,
                             const LineSettings& lines);

}  // namespace hikari
