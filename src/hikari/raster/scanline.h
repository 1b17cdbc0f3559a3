#pragma once
// The scanline method (the lecture's Algorithm 4.1, スキャンライン法): hidden-surface removal one
// scanline at a time, from an edge table and an active edge list, without a per-pixel depth buffer.

#include <cstdint>
#include <span>
#include <vector>

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

/// One iteration of Alg 4.1's loop, as the algorithm saw it (`hikari explain -m scanline --row Y`).
/// Depths are the depth key ScreenVertex::position.z (smaller is nearer).
struct ScanlineRowTrace {
    /// An edge-table entry: a non-horizontal triangle edge from its upper end point down.
    struct Edge {
        uint32_t triangle = 0;  ///< index into the ScreenTriangle list
        double x_top = 0, y_top = 0, z_top = 0, dx_dy = 0, dz_dy = 0;
        int first_row = 0, last_row = 0;  ///< the rows it is active on (inclusive)
    };
    /// An active-edge-list entry: an edge's intercept with the scan line y = row + 0.5.
    struct Active {
        uint32_t triangle = 0;
        double x = 0, z = 0;
    };
    /// A scan segment: a triangle's part of the scan line, pixel centres x_left <= x < x_right.
    struct Segment {
        uint32_t triangle = 0;
        double x_left = 0, x_right = 0, z_left = 0, dz_dx = 0;
    };
    /// Pixels [first, end) of a sample span (between consecutive segment end points, from x_begin
    /// to x_end), and the triangle visible on them; a span whose segments cross in depth is
    /// reported in pieces, one per visible triangle.
    struct Span {
        double x_begin = 0, x_end = 0;
        int first = 0, end = 0;
        uint32_t triangle = 0;
    };
    std::vector<Edge> starting;     ///< the edge-table bucket of this row
    std::vector<Active> active;     ///< the active edge list, sorted by x
    std::vector<Segment> segments;  ///< in the order the triangles' edge pairs complete
    std::vector<Span> spans;        ///< left to right
};

/// scanline_visibility, also recording the iteration for scan line `row` into `trace`. The same
/// code runs: the render's loop reports to an observer that does nothing by default.
VisibilityBuffer scanline_visibility_at(std::span<const ScreenTriangle> triangles, int width,
                                        int height, int row, ScanlineRowTrace& trace);

/// scanline_visibility, also marking in `span_starts` (row-major, 1 = marked) the first pixel of
/// every sample span and of every piece a depth crossing splits one into (`--aov spans`).
VisibilityBuffer scanline_visibility_spans(std::span<const ScreenTriangle> triangles, int width,
                                           int height, std::vector<uint8_t>& span_starts);

/// The `scanline` method: vertex stage (raster/vertex_pipeline.h), scanline_visibility, then the
/// shared deferred shading pass (raster/shade_visibility.h).
Framebuffer render_scanline(const Scene& scene, Film film, const RenderSettings& settings = {},
                            const RasterSettings& raster = {});

}  // namespace hikari
