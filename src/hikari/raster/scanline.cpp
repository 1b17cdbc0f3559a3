#include "hikari/raster/scanline.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>

#include "hikari/core/parallel.h"
#include "hikari/raster/polygon_fill.h"
#include "hikari/raster/shade_visibility.h"

namespace hikari {
namespace {

/// Rows per parallel band. Fixed, so the incremental edge updates (re-seeded at every band start)
/// and hence the result do not depend on the thread count.
constexpr int k_band_rows = 16;
constexpr uint32_t k_no_edge = UINT32_MAX;

/// One non-horizontal triangle edge in the edge table (ET), from its upper end point down.
struct EdgeRecord {
    double x_top = 0, y_top = 0, z_top = 0;
    double dx_dy = 0;                 ///< x step per scanline
    double dz_dy = 0;                 ///< depth step per scanline along the edge
    int first_row = 0, last_row = 0;  ///< rows (inclusive, clipped to the image) it is active on
    uint32_t triangle = 0;
};

/// An entry of the active edge list (AEL): an edge with its intercept at the current scanline.
struct ActiveEdge {
    double x = 0, z = 0;
    uint32_t edge = 0;
};

/// A scan segment: the intersection of the scan plane with one triangle, covering the pixel
/// centres x_left <= x < x_right; its depth is affine in x with the triangle's plane slope.
struct Segment {
    double x_left = 0, x_right = 0, z_left = 0, dz_dx = 0;
    uint32_t triangle = 0;

    double depth_at(double x) const { return z_left + (x - x_left) * dz_dx; }
};

/// A segment end point in the x sort.
struct EndPoint {
    double x = 0;
    uint32_t segment = 0;
    bool opens = false;
};

/// The edge table: edges bucketed by the first scanline they are active on, plus each triangle's
/// depth slope along x.
struct EdgeTable {
    std::vector<EdgeRecord> edges;
    std::vector<uint32_t> order;  ///< edge indices grouped by first_row
    std::vector<uint32_t>
        bucket_begin;           ///< order[bucket_begin[j] .. bucket_begin[j + 1]) start on row j
    std::vector<double> dz_dx;  ///< per ScreenTriangle
};

/// Per-thread scratch, reused from band to band (no allocation per row in steady state).
struct Scratch {
    std::vector<ActiveEdge> active;
    std::vector<uint32_t> pending_edge;  ///< per triangle: its first active edge this row
    std::vector<Segment> segments;
    std::vector<EndPoint> end_points;
    std::vector<uint32_t> open;      ///< segments spanning the current sample span
    std::vector<uint32_t> open_pos;  ///< per segment: its index in `open`
};

/// The render's observer: told nothing, costs nothing.
struct NoRowObserver {
    static constexpr bool k_active = false;
    void row(int, const EdgeTable&, const Scratch&) const {}
    void span(int, double, double, int, int, uint32_t) const {}
};

/// Records one scan line's iteration (explain).
struct RowRecorder {
    static constexpr bool k_active = true;
    int row_index;
    ScanlineRowTrace& trace;

    void row(int j, const EdgeTable& table, const Scratch& s) const {
        if (j != row_index) return;
        for (uint32_t k = table.bucket_begin[j]; k < table.bucket_begin[j + 1]; ++k) {
            const EdgeRecord& e = table.edges[table.order[k]];
            trace.starting.push_back(
                {e.triangle, e.x_top, e.y_top, e.z_top, e.dx_dy, e.dz_dy, e.first_row, e.last_row});
        }
        for (const ActiveEdge& a : s.active)
            trace.active.push_back({table.edges[a.edge].triangle, a.x, a.z});
        std::stable_sort(trace.active.begin(), trace.active.end(),
                         [](const auto& a, const auto& b) { return a.x < b.x; });
        for (const Segment& g : s.segments)
            trace.segments.push_back({g.triangle, g.x_left, g.x_right, g.z_left, g.dz_dx});
    }
    void span(int j, double x_begin, double x_end, int first, int end, uint32_t triangle) const {
        if (j == row_index && first < end)
            trace.spans.push_back({x_begin, x_end, first, end, triangle});
    }
};

/// Marks where each span piece starts, on every row (a row belongs to one thread).
struct SpanMarker {
    static constexpr bool k_active = true;
    int width;
    uint8_t* mark;
    void row(int, const EdgeTable&, const Scratch&) const {}
    void span(int j, double, double, int first, int end, uint32_t) const {
        if (first < end) mark[static_cast<size_t>(j) * width + first] = 1;
    }
};

PolygonVertex to_vertex(const ScreenVertex& v) {
    return {v.position.x, v.position.y, v.position.z};
}

/// Alg 4.1, step 1 (the triangles arrive projected): the edge table.
EdgeTable build_edge_table(std::span<const ScreenTriangle> triangles, int height) {
    EdgeTable table;
    table.dz_dx.assign(triangles.size(), 0.0);
    for (size_t t = 0; t < triangles.size(); ++t) {
        const PolygonVertex a = to_vertex(triangles[t].v[0]);
        const PolygonVertex b = to_vertex(triangles[t].v[1]);
        const PolygonVertex c = to_vertex(triangles[t].v[2]);
        const double area2 = signed_area2(a, b, c);
        if (!std::isfinite(area2) || area2 == 0 || !std::isfinite(a.z + b.z + c.z))
            continue;  // edge-on or invalid: covers no pixel centre
        // z = z_a + dz_dx (x - x_a) + dz_dy (y - y_a) (the plane stays planar after projection)
        table.dz_dx[t] = ((b.z - a.z) * (c.y - a.y) - (c.z - a.z) * (b.y - a.y)) / area2;
        const PolygonVertex corners[3] = {a, b, c};
        for (int k = 0; k < 3; ++k) {
            const auto [top, bottom] = canonical_edge(corners[k], corners[(k + 1) % 3]);
            const PixelRange rows = centre_range(top.y, bottom.y, height);
            if (rows.empty()) continue;  // horizontal, between two scanlines, or off-screen
            EdgeRecord e;
            e.x_top = top.x;
            e.y_top = top.y;
            e.z_top = top.z;
            e.dx_dy = (bottom.x - top.x) / (bottom.y - top.y);
            e.dz_dy = (bottom.z - top.z) / (bottom.y - top.y);
            e.first_row = rows.begin;
            e.last_row = rows.end - 1;
            e.triangle = static_cast<uint32_t>(t);
            table.edges.push_back(e);
        }
    }
    // bucket the edges by starting scanline (counting sort)
    table.bucket_begin.assign(static_cast<size_t>(height) + 1, 0);
    for (const EdgeRecord& e : table.edges) ++table.bucket_begin[e.first_row + 1];
    for (int j = 0; j < height; ++j) table.bucket_begin[j + 1] += table.bucket_begin[j];
    table.order.resize(table.edges.size());
    std::vector<uint32_t> cursor(table.bucket_begin.begin(), table.bucket_begin.end() - 1);
    for (size_t i = 0; i < table.edges.size(); ++i)
        table.order[cursor[table.edges[i].first_row]++] = static_cast<uint32_t>(i);
    return table;
}

/// The edge's intercept with scanline `row`, computed directly (when it enters the AEL).
ActiveEdge activate(const EdgeTable& table, uint32_t edge, int row) {
    const EdgeRecord& e = table.edges[edge];
    const double dy = (row + 0.5) - e.y_top;
    return {e.x_top + dy * e.dx_dy, e.z_top + dy * e.dz_dy, edge};
}

/// Alg 4.1: the scan segments of this row, pairing each triangle's two active edges.
void form_segments(const EdgeTable& table, int width, Scratch& s) {
    s.segments.clear();
    for (uint32_t k = 0; k < s.active.size(); ++k) {
        const uint32_t t = table.edges[s.active[k].edge].triangle;
        if (s.pending_edge[t] == k_no_edge) {
            s.pending_edge[t] = k;
            continue;
        }
        const ActiveEdge* l = &s.active[s.pending_edge[t]];
        const ActiveEdge* r = &s.active[k];
        s.pending_edge[t] = k_no_edge;
        if (r->x < l->x) std::swap(l, r);
        // a segment without a pixel centre can be visible nowhere
        if (centre_range(l->x, r->x, width).empty()) continue;
        s.segments.push_back({l->x, r->x, l->z, table.dz_dx[t], t});
    }
    for (const ActiveEdge& a : s.active) s.pending_edge[table.edges[a.edge].triangle] = k_no_edge;
}

/// Nearer of two open segments at x: smaller depth, then the one getting nearer to the right,
/// then the smaller triangle index (so ties resolve the same way everywhere).
bool nearer(const Segment& a, const Segment& b, double x) {
    const double za = a.depth_at(x), zb = b.depth_at(x);
    if (za != zb) return za < zb;
    if (a.dz_dx != b.dz_dx) return a.dz_dx < b.dz_dx;
    return a.triangle < b.triangle;
}

/// Alg 4.1: in one sample span (pixel columns `cols`), the visible segment; where another open
/// segment comes nearer inside the span (interpenetration), the span is split at the crossing.
/// The observer hears of each piece: row j, the piece's x interval, its pixels and triangle.
template <class Observer>
void fill_span(const Scratch& s, PixelRange cols, uint32_t* row, int j, double x_begin,
               double x_end, const Observer& observer) {
    double x = cols.begin + 0.5;
    const double x_last = cols.end - 0.5;
    uint32_t best = s.open[0];
    for (uint32_t o : s.open)
        if (nearer(s.segments[o], s.segments[best], x)) best = o;
    int i = cols.begin;
    for (;;) {
        // the first crossing to the right: only segments with a smaller slope can overtake, so
        // the slope of the visible segment falls with every split and the walk ends
        const Segment& b = s.segments[best];
        double cross_x = x_last;
        uint32_t next = k_no_edge;
        for (uint32_t o : s.open) {
            const Segment& c = s.segments[o];
            if (!(c.dz_dx < b.dz_dx)) continue;
            const double gap = std::max(0.0, c.depth_at(x) - b.depth_at(x));
            const double xc = x + gap / (b.dz_dx - c.dz_dx);
            if (xc < cross_x ||
                (xc == cross_x && next != k_no_edge && nearer(c, s.segments[next], xc))) {
                cross_x = xc;
                next = o;
            }
        }
        if (next == k_no_edge) break;
        const int split = std::min(first_centre_at_or_after(cross_x, cols.end), cols.end);
        if constexpr (Observer::k_active) observer.span(j, x_begin, cross_x, i, split, b.triangle);
        x_begin = cross_x;
        for (; i < split; ++i) row[i] = b.triangle;
        x = cross_x;
        best = next;
    }
    const uint32_t id = s.segments[best].triangle;
    if constexpr (Observer::k_active) observer.span(j, x_begin, x_end, i, cols.end, id);
    for (; i < cols.end; ++i) row[i] = id;
}

/// Alg 4.1: sort the end points by x, sweep the sample spans between them, fill each.
template <class Observer>
void resolve_row(int width, Scratch& s, uint32_t* row, int j, const Observer& observer) {
    s.end_points.clear();
    for (uint32_t k = 0; k < s.segments.size(); ++k) {
        s.end_points.push_back({s.segments[k].x_left, k, true});
        s.end_points.push_back({s.segments[k].x_right, k, false});
    }
    std::sort(s.end_points.begin(), s.end_points.end(),
              [](const EndPoint& a, const EndPoint& b) { return a.x < b.x; });
    s.open.clear();
    if (s.open_pos.size() < s.segments.size()) s.open_pos.resize(s.segments.size());
    for (size_t k = 0; k < s.end_points.size(); ++k) {
        const EndPoint& e = s.end_points[k];
        if (e.opens) {
            s.open_pos[e.segment] = static_cast<uint32_t>(s.open.size());
            s.open.push_back(e.segment);
        } else {
            const uint32_t pos = s.open_pos[e.segment];
            s.open[pos] = s.open.back();
            s.open_pos[s.open[pos]] = pos;
            s.open.pop_back();
        }
        if (s.open.empty() || k + 1 == s.end_points.size()) continue;
        const PixelRange cols = centre_range(e.x, s.end_points[k + 1].x, width);
        if (!cols.empty()) fill_span(s, cols, row, j, e.x, s.end_points[k + 1].x, observer);
    }
}

/// Alg 4.1 over rows [row_begin, row_end): the AEL is seeded with the edges crossing the first row,
/// then updated incrementally from one scanline to the next.
template <class Observer>
void scan_band(const EdgeTable& table, int width, int row_begin, int row_end, Scratch& s,
               uint32_t* pixels, const Observer& observer) {
    s.active.clear();
    for (uint32_t e = 0; e < table.edges.size(); ++e)
        if (table.edges[e].first_row < row_begin && table.edges[e].last_row >= row_begin)
            s.active.push_back(activate(table, e, row_begin));
    for (int j = row_begin; j < row_end; ++j) {
        // add the edges that start on this scanline (the ET bucket)
        for (uint32_t k = table.bucket_begin[j]; k < table.bucket_begin[j + 1]; ++k)
            s.active.push_back(activate(table, table.order[k], j));
        form_segments(table, width, s);
        if constexpr (Observer::k_active) observer.row(j, table, s);
        resolve_row(width, s, pixels + static_cast<size_t>(j) * width, j, observer);
        // update the AEL: drop the edges ending here, step the rest to the next scanline
        size_t kept = 0;
        for (const ActiveEdge& a : s.active) {
            const EdgeRecord& e = table.edges[a.edge];
            if (e.last_row <= j) continue;
            s.active[kept++] = {a.x + e.dx_dy, a.z + e.dz_dy, a.edge};
        }
        s.active.resize(kept);
    }
}

template <class Observer>
VisibilityBuffer scanline_pass(std::span<const ScreenTriangle> triangles, int width, int height,
                               const Observer& observer) {
    VisibilityBuffer out;
    out.width = std::max(width, 0);
    out.height = std::max(height, 0);
    out.triangle.assign(static_cast<size_t>(out.width) * out.height, k_no_triangle);
    if (out.triangle.empty() || triangles.empty()) return out;

    const EdgeTable table = build_edge_table(triangles, out.height);
    tbb::enumerable_thread_specific<Scratch> scratch([&] {
        Scratch s;
        s.pending_edge.assign(triangles.size(), k_no_edge);
        return s;
    });
    const int bands = (out.height + k_band_rows - 1) / k_band_rows;
    hikari::parallel_for(tbb::blocked_range<int>(0, bands, 1),
                         [&](const tbb::blocked_range<int>& r) {
                             Scratch& s = scratch.local();
                             for (int b = r.begin(); b != r.end(); ++b)
                                 scan_band(table, out.width, b * k_band_rows,
                                           std::min(out.height, (b + 1) * k_band_rows), s,
                                           out.triangle.data(), observer);
                         });
    return out;
}

}  // namespace

VisibilityBuffer scanline_visibility(std::span<const ScreenTriangle> triangles, int width,
                                     int height) {
    return scanline_pass(triangles, width, height, NoRowObserver{});
}

VisibilityBuffer scanline_visibility_spans(std::span<const ScreenTriangle> triangles, int width,
                                           int height, std::vector<uint8_t>& span_starts) {
    span_starts.assign(static_cast<size_t>(std::max(width, 0)) * std::max(height, 0), 0);
    return scanline_pass(triangles, width, height, SpanMarker{width, span_starts.data()});
}

VisibilityBuffer scanline_visibility_at(std::span<const ScreenTriangle> triangles, int width,
                                        int height, int row, ScanlineRowTrace& trace) {
    trace = {};
    return scanline_pass(triangles, width, height, RowRecorder{row, trace});
}

Framebuffer render_scanline(const Scene& scene, Film film, const RenderSettings& settings,
                            const RasterSettings& raster) {
    return render_raster(
        scene, std::move(film), settings, raster, [&](auto triangles, int width, int height) {
            if (!settings.stats) return scanline_visibility(triangles, width, height);
            std::vector<uint8_t> starts;
            VisibilityBuffer vis = scanline_visibility_spans(triangles, width, height, starts);
            uint64_t spans = 0;
            for (const uint8_t s : starts) spans += s;
            settings.stats->raster_fragments += spans;
            return vis;
        });
}

}  // namespace hikari
