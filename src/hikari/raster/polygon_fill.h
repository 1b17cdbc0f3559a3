#pragma once
// Pixel-centre coverage of screen-space polygons with the top-left fill rule, shared by the
// scanline method and the depth sort (and by their tests' reference ray caster in spirit).
//
// The rule, stated as a scanline walk: sample row j at y = j + 0.5 and pixel i at x = i + 0.5; an
// edge is active on a row when y_top <= y < y_bottom (half-open, so horizontal edges never are and
// a bottom edge never covers); a polygon covers the centres x with x_left <= x < x_right between
// its active edges. That is the top-left rule of the half-space rasterizers (a centre on a left or
// top edge is inside, on a right or bottom edge outside), so two polygons sharing an edge cover
// each centre on it exactly once: no cracks, no double coverage.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>

namespace hikari {

/// A polygon vertex in screen space, in double precision so that split pieces (depth sort) keep
/// their cut vertices exactly shared: x, y in pixels (top-left origin), z the NDC depth in [0, 1].
struct PolygonVertex {
    double x = 0, y = 0, z = 0;
};

/// A half-open range [begin, end) of pixel indices.
struct PixelRange {
    int begin = 0;
    int end = 0;
    bool empty() const { return begin >= end; }
};

/// The first index k in [0, count] whose centre k + 0.5 is >= `v` (NaN gives 0).
inline int first_centre_at_or_after(double v, int count) {
    const double k = std::ceil(v - 0.5);
    if (!(k > 0)) return 0;
    return k >= count ? count : static_cast<int>(k);
}

/// Indices k in [0, count) whose centres k + 0.5 lie in the half-open interval [lo, hi).
inline PixelRange centre_range(double lo, double hi, int count) {
    return {first_centre_at_or_after(lo, count), first_centre_at_or_after(hi, count)};
}

/// The upper (then leftmost) end point of an edge first: two polygons sharing an edge then compute
/// bit-identical intercepts with every scanline, whichever way round they list it.
inline std::pair<PolygonVertex, PolygonVertex> canonical_edge(PolygonVertex a, PolygonVertex b) {
    if (b.y < a.y || (b.y == a.y && b.x < a.x)) std::swap(a, b);
    return {a, b};
}

/// Twice the signed area of triangle (a, b, c) in the xy plane; exactly zero for collinear float
/// inputs, since differences and products of floats are exact in double.
inline double signed_area2(PolygonVertex a, PolygonVertex b, PolygonVertex c) {
    return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
}

/// Calls `fn(i, j)` for every pixel centre (i + 0.5, j + 0.5) of a width × height image that the
/// convex polygon `poly` covers under the top-left rule, on rows [row_begin, row_end) only (a band
/// of the image: the pixels are those fill_convex_polygon gives on these rows). Vertices may be in
/// either winding order.
template <class Fn>
void fill_convex_polygon_rows(std::span<const PolygonVertex> poly, int width, int height,
                              int row_begin, int row_end, Fn&& fn) {
    const size_t n = poly.size();
    if (n < 3) return;
    double y_min = std::numeric_limits<double>::infinity();
    double y_max = -y_min;
    for (const PolygonVertex& v : poly) {
        y_min = std::min(y_min, v.y);
        y_max = std::max(y_max, v.y);
    }
    const PixelRange rows = centre_range(y_min, y_max, height);
    for (int j = std::max(rows.begin, row_begin); j < std::min(rows.end, row_end); ++j) {
        const double y = j + 0.5;
        double x_left = std::numeric_limits<double>::infinity();
        double x_right = -x_left;
        for (size_t k = 0; k < n; ++k) {
            const auto [top, bottom] = canonical_edge(poly[k], poly[(k + 1) % n]);
            if (!(top.y <= y && y < bottom.y)) continue;
            const double x = top.x + (y - top.y) * ((bottom.x - top.x) / (bottom.y - top.y));
            x_left = std::min(x_left, x);
            x_right = std::max(x_right, x);
        }
        if (!(x_left < x_right)) continue;
        const PixelRange cols = centre_range(x_left, x_right, width);
        for (int i = cols.begin; i < cols.end; ++i) fn(i, j);
    }
}

/// Calls `fn(i, j)` for every pixel centre (i + 0.5, j + 0.5) of a width × height image that the
/// convex polygon `poly` covers under the top-left rule. Vertices may be in either winding order.
template <class Fn>
void fill_convex_polygon(std::span<const PolygonVertex> poly, int width, int height, Fn&& fn) {
    fill_convex_polygon_rows(poly, width, height, 0, height, std::forward<Fn>(fn));
}

}  // namespace hikari
