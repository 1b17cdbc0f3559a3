#pragma once
// Anti-aliased lines: a LineDrawing turned into pixels. Each segment is a rectangle of the line
// width (butt ends, as SVG strokes them); a pixel takes the part of its square the rectangle
// covers, measured in the segment's own frame (an analytic box filter, exact for lines along
// the axes), so that the PNG and the SVG of one drawing agree.

#include <span>

#include "hikari/frame/film.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/frame/line_drawing.h"

namespace hikari {

/// Coverage of the pixel whose centre is at distance `across` from the axis of a segment
/// `length` long and `width` wide, running along unit direction (ux, uy), and at `along` from
/// its start (all in pixels): the part of the pixel square inside the stroke's band, times the
/// part between its ends. Each part is exact (the square's area projected onto the band's
/// normal, or onto its direction, is a trapezoid), so a long line of any angle deposits its
/// area exactly; only the corners at its ends are approximated by the product.
float line_coverage(float across, float along, float length, float width, float ux, float uy);

/// Draws `drawing` over its background into `film` (width × height of the drawing): each
/// segment in turn, over what is there, with its coverage as opacity (Porter & Duff 1984), in
/// sRGB-encoded colour as SVG renderers composite strokes, so that the SVG of io/svg_write.h shows
/// the same image; pixels no segment touches keep the background exactly. With `aov_buffers`, the
/// depth AOV holds
/// the eye distance, and the id AOV 1 + the id, of the segment covering most of each pixel;
/// the normal AOV stays zero. Parallel over bands of rows, each taking its segments in the
/// drawing's order: the result does not depend on the thread count.
/// Surfaces a line drawing may be hidden behind (`--wireframe-overlay`): a segment covers a
/// pixel only where its eye distance is at most depth[pixel] · (1 + tolerance).
struct LineOcclusion {
    std::span<const float> depth;  ///< eye distance per pixel, row-major (empty: nothing hides)
    float tolerance = 0.0f;        ///< a fraction of the depth
};

Framebuffer rasterize_lines(const LineDrawing& drawing, Film film, bool aov_buffers,
                            LineOcclusion occlusion = {});

}  // namespace hikari
