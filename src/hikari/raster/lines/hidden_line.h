#pragma once
// Hidden-line removal (the lecture's Fig 4.1c): only the visible parts of the edges, found in
// object space, so that the result is a set of segments exact at any resolution.
//
// The method is Appel's (1967) in its modern form: an edge's visibility can only change where,
// seen from the eye, it passes behind the boundary of a face (its projection crosses a projected
// edge of that face) or through the face (it pierces the face's plane). Splitting each edge at
// all such points of every face that can hide it leaves pieces whose visibility is constant, so
// one depth test at each piece's midpoint classifies the whole piece. The faces that can hide an
// edge are found in a screen-space grid of the projected triangles.

#include "hikari/frame/film.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/frame/line_drawing.h"
#include "hikari/frame/render_settings.h"
#include "hikari/raster/lines/line_settings.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// The visible parts of `scene`'s lines: the model edges (raster/model_edges.h), the silhouette
/// edges (between a face turned to the eye and one turned away, triangulation diagonals
/// included) and the intersection lines of faces that pierce each other. A line is hidden where
/// a face other than its own lies in front of it; with lines.cull_back_faces, faces seen from
/// behind neither hide nor are drawn. Consecutive visible pieces of a line are merged; the
/// order of the segments does not depend on the thread count.
LineDrawing draw_hidden_lines(const Scene& scene, const LineSettings& lines);

/// The `hiddenline` method: draw_hidden_lines rasterized with anti-aliasing
/// (raster/line_raster.h).
Framebuffer render_hidden_lines(const Scene& scene, Film film, const RenderSettings& settings,
                                const LineSettings& lines);

}  // namespace hikari
