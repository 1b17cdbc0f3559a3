#include "hikari/raster/scanline.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <utility>
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
/// Its upper end point is a vertex of a ScreenTriangle, so float holds it exactly (40 bytes a
/// record rather than 56). No member initializers: the table is allocated without zeroing it,
/// then written by several threads, which spreads the page faults of a large table over them.
struct EdgeRecord {
    float x_top, y_top, z_top;
    double dx_dy;             ///< x step per scanline
    double dz_dy;             ///< depth step per scanline along the edge
    int first_row, last_row;  ///< rows (inclusive, clipped to the image) it is active on
    uint32_t triangle;
};

/// An entry of the active edge list (AEL): an edge with its intercept at the current scanline,
/// carrying the steps and the end row it is updated with, so that the per-row update and the
/// segment pairing read the AEL alone and never the (much larger, randomly indexed) edge table.
struct ActiveEdge {
    double x = 0, z = 0;
    double dx_dy = 0, dz_dy = 0;
    int last_row = 0;
    uint32_t triangle = 0;
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
    std::unique_ptr<EdgeRecord[]> edge_storage;
    std::span<EdgeRecord> edges;
    std::vector<uint32_t> order;  ///< edge indices grouped by first_row
    std::vector<uint32_t>
        bucket_begin;  ///< order[bucket_begin[j] .. bucket_begin[j + 1]) start on row j
    /// Per band, the edges already active on its first row (started above it), in edge order:
    /// band_seed[band_seed_begin[b] .. band_seed_begin[b + 1]) seed band b's AEL. Listing them
    /// here once costs the edges' band crossings; finding them at every band start by a scan of
    /// the whole table cost (bands × edges), most of the pass on large meshes.
    std::vector<uint32_t> band_seed;
    std::vector<uint32_t> band_seed_begin;
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
        for (const ActiveEdge& a : s.active) trace.active.push_back({a.triangle, a.x, a.z});
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

/// Alg 4.1, step 1 for triangle t: writes its edges that cross a scanline into `out` and returns
/// how many (0 to 3); `dz_dx` gets its depth slope along x.
int triangle_edges(const ScreenTriangle& triangle, uint32_t t, int height, EdgeRecord* out,
                   double& dz_dx) {
    const PolygonVertex a = to_vertex(triangle.v[0]);
    const PolygonVertex b = to_vertex(triangle.v[1]);
    const PolygonVertex c = to_vertex(triangle.v[2]);
    const double area2 = signed_area2(a, b, c);
    if (!std::isfinite(area2) || area2 == 0 || !std::isfinite(a.z + b.z + c.z))
        return 0;  // edge-on or invalid: covers no pixel centre
    // z = z_a + dz_dx (x - x_a) + dz_dy (y - y_a) (the plane stays planar after projection)
    dz_dx = ((b.z - a.z) * (c.y - a.y) - (c.z - a.z) * (b.y - a.y)) / area2;
    const PolygonVertex corners[3] = {a, b, c};
    int count = 0;
    for (int k = 0; k < 3; ++k) {
        const auto [top, bottom] = canonical_edge(corners[k], corners[(k + 1) % 3]);
        const PixelRange rows = centre_range(top.y, bottom.y, height);
        if (rows.empty()) continue;  // horizontal, between two scanlines, or off-screen
        EdgeRecord& e = out[count++];
        e.x_top = static_cast<float>(top.x);
        e.y_top = static_cast<float>(top.y);
        e.z_top = static_cast<float>(top.z);
        e.dx_dy = (bottom.x - top.x) / (bottom.y - top.y);
        e.dz_dy = (bottom.z - top.z) / (bottom.y - top.y);
        e.first_row = rows.begin;
        e.last_row = rows.end - 1;
        e.triangle = t;
    }
    return count;
}

/// Alg 4.1, step 1 (the triangles arrive projected): the edge table. The edges are listed in
/// triangle order whatever the thread count: each fixed chunk of triangles counts its edges, then
/// writes them at its prefix-sum offset.
EdgeTable build_edge_table(std::span<const ScreenTriangle> triangles, int height) {
    EdgeTable table;
    table.dz_dx.assign(triangles.size(), 0.0);
    constexpr size_t k_chunk = 4096;
    const size_t chunks = (triangles.size() + k_chunk - 1) / k_chunk;
    std::vector<size_t> chunk_begin(chunks + 1, 0);
    auto for_each_chunk = [&](auto&& body) {
        hikari::parallel_for(
            tbb::blocked_range<size_t>(0, chunks, 1), [&](const tbb::blocked_range<size_t>& r) {
                for (size_t c = r.begin(); c != r.end(); ++c)
                    body(c, c * k_chunk, std::min(triangles.size(), (c + 1) * k_chunk));
            });
    };
    for_each_chunk([&](size_t c, size_t t0, size_t t1) {
        EdgeRecord three[3];
        size_t count = 0;
        for (size_t t = t0; t < t1; ++t)
            count += triangle_edges(triangles[t], static_cast<uint32_t>(t), height, three,
                                    table.dz_dx[t]);
        chunk_begin[c + 1] = count;
    });
    for (size_t c = 0; c < chunks; ++c) chunk_begin[c + 1] += chunk_begin[c];
    table.edge_storage = std::make_unique_for_overwrite<EdgeRecord[]>(chunk_begin[chunks]);
    table.edges = {table.edge_storage.get(), chunk_begin[chunks]};
    for_each_chunk([&](size_t c, size_t t0, size_t t1) {
        EdgeRecord* out = table.edges.data() + chunk_begin[c];
        double dz_dx = 0;
        for (size_t t = t0; t < t1; ++t)
            out += triangle_edges(triangles[t], static_cast<uint32_t>(t), height, out, dz_dx);
    });
    // bucket the edges by starting scanline (counting sort)
    table.bucket_begin.assign(static_cast<size_t>(height) + 1, 0);
    for (const EdgeRecord& e : table.edges) ++table.bucket_begin[e.first_row + 1];
    for (int j = 0; j < height; ++j) table.bucket_begin[j + 1] += table.bucket_begin[j];
    table.order.resize(table.edges.size());
    std::vector<uint32_t> cursor(table.bucket_begin.begin(), table.bucket_begin.end() - 1);
    for (size_t i = 0; i < table.edges.size(); ++i)
        table.order[cursor[table.edges[i].first_row]++] = static_cast<uint32_t>(i);
    // the band seeds (counting sort again): edge e seeds every band whose first row lies in
    // (first_row, last_row]
    const int bands = (height + k_band_rows - 1) / k_band_rows;
    auto seeded_bands = [](const EdgeRecord& e) {
        return std::pair{e.first_row / k_band_rows + 1, e.last_row / k_band_rows + 1};
    };
    table.band_seed_begin.assign(static_cast<size_t>(bands) + 1, 0);
    for (const EdgeRecord& e : table.edges) {
        const auto [b0, b1] = seeded_bands(e);
        for (int b = b0; b < b1; ++b) ++table.band_seed_begin[b + 1];
    }
    for (int b = 0; b < bands; ++b) table.band_seed_begin[b + 1] += table.band_seed_begin[b];
    table.band_seed.resize(table.band_seed_begin[bands]);
    cursor.assign(table.band_seed_begin.begin(), table.band_seed_begin.end() - 1);
    for (size_t i = 0; i < table.edges.size(); ++i) {
        const auto [b0, b1] = seeded_bands(table.edges[i]);
        for (int b = b0; b < b1; ++b) table.band_seed[cursor[b]++] = static_cast<uint32_t>(i);
    }
    return table;
}

/// The edge's intercept with scanline `row`, computed directly (when it enters the AEL).
ActiveEdge activate(const EdgeTable& table, uint32_t edge, int row) {
    const EdgeRecord& e = table.edges[edge];
    const double dy = (row + 0.5) - e.y_top;
    return {
        e.x_top + dy * e.dx_dy, e.z_top + dy * e.dz_dy, e.dx_dy, e.dz_dy, e.last_row, e.triangle};
}

/// Alg 4.1: the scan segments of this row, pairing each triangle's two active edges.
void form_segments(const EdgeTable& table, int width, Scratch& s) {
    s.segments.clear();
    for (uint32_t k = 0; k < s.active.size(); ++k) {
        const uint32_t t = s.active[k].triangle;
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
    for (const ActiveEdge& a : s.active) s.pending_edge[a.triangle] = k_no_edge;
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
    const int band = row_begin / k_band_rows;
    for (uint32_t k = table.band_seed_begin[band]; k < table.band_seed_begin[band + 1]; ++k)
        s.active.push_back(activate(table, table.band_seed[k], row_begin));
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
            if (a.last_row <= j) continue;
            ActiveEdge& stepped = s.active[kept++];
            stepped = a;
            stepped.x += a.dx_dy;
            stepped.z += a.dz_dy;
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
