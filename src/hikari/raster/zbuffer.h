#pragma once
// The Z-buffer method (the lecture's Alg 4.2, Catmull 1974): every pixel keeps the depth of the
// nearest surface drawn so far, and a fragment is written only when it is nearer still.

#include <span>

#include "hikari/frame/film.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/frame/render_settings.h"
#include "hikari/raster/raster_settings.h"
#include "hikari/raster/screen_triangle.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// Hidden-surface removal by Z-buffer: rasterizes `triangles` (half-space, top-left rule, pixel
/// centres) into a width × height visibility buffer. Z is the view depth 1 / inv_w interpolated
/// perspective-correctly, initialised to infinity; a fragment wins when z < Z, so on equal depth
/// the earlier triangle stays. Parallel over tiles, each with the triangles binned to it in
/// order: the result does not depend on the thread count. `control` may be null.
VisibilityBuffer zbuffer_visibility(std::span<const ScreenTriangle> triangles, int width,
                                    int height, RenderControl* control = nullptr);

/// The `zbuffer` method: vertex stage (raster/vertex_pipeline.h), zbuffer_visibility, then the
/// shared deferred shading pass (raster/shade_visibility.h).
Framebuffer render_zbuffer(const Scene& scene, Film film, const RenderSettings& settings = {},
                           const RasterSettings& raster = {});

}  // namespace hikari
