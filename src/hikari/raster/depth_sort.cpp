#include "hikari/raster/depth_sort.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "hikari/core/cancel.h"
#include "hikari/core/parallel.h"
#include "hikari/raster/box_grid.h"
#include "hikari/raster/polygon_fill.h"
#include "hikari/raster/shade_visibility.h"

namespace hikari {
namespace {

/// The cuts the depth sort may make per polygon of the scene before it paints the order it has
/// (DepthSortCounts::gave_up): scenes that interpenetrate here and there cut each polygon a few
/// times at most.
constexpr int64_t k_splits_per_polygon = 4;

/// The polygons the sort may look at (a Q scanned for P, a member of a cycle, an entry a split
/// moves in the list) before it paints the order it has: an ordinary scene looks at a few per
/// polygon, but a tangle of large polygons that all pierce one another makes every step scan
/// all of them, so cuts alone would not bound the time (8,000 such triangles took 46 s).
/// About a second of work, more for larger scenes; a trace records every step, so less.
constexpr int64_t k_work_base = int64_t{1} << 24;
constexpr int64_t k_work_base_traced = int64_t{1} << 21;
constexpr int64_t k_work_per_polygon = 64;

/// Rows per band of the parallel paint.
constexpr int k_paint_band_rows = 8;

/// Relative tolerance of the plane-side and projection tests: a vertex this close to a plane counts
/// as on it, so neighbours sharing an edge or a vertex never count as straddling each other.
constexpr double k_side_epsilon = 1e-9;
/// Polygons with less area (in pixels squared) are dropped after a split: they hold no pixel
/// centre.
constexpr double k_min_area2 = 1e-12;

/// Where a polygon's vertices lie relative to a plane (bit set).
enum SideBits : int { k_on_plane = 0, k_behind = 1, k_in_front = 2, k_straddles = 3 };

/// A convex polygon of the depth sort: a triangle or a piece of one, on the triangle's plane.
struct Polygon {
    uint32_t first = 0, count = 0;  ///< vertices [first, first + count) of the vertex pool
    uint32_t source = 0;            ///< the ScreenTriangle it came from: every piece keeps it
    double a = 0, b = 0, c = 0;     ///< plane z = a x + b y + c (z grows away from the viewer)
    double x_min = 0, x_max = 0, y_min = 0, y_max = 0, z_min = 0, z_max = 0;
};

/// What the overlap tests decide for the current polygon P.
enum class Step { paint, move_q, split_q_by_p, split_p_by_q, bisect_p };

/// Newell, Newell & Sancha 1972, over convex polygons kept in a flat vertex pool.
class DepthSorter {
  public:
    /// `trace`, when not null, hears of every step.
    explicit DepthSorter(std::span<const ScreenTriangle> triangles,
                         DepthSortTrace* trace = nullptr);
    /// The polygons in painting order, back to front.
    void sort();
    /// Paints the first `limit` polygons of the order, back to front.
    void paint(VisibilityBuffer& out, uint32_t limit = UINT32_MAX) const;

  private:
    std::span<const PolygonVertex> vertices(const Polygon& p) const {
        return {m_vertices.data() + p.first, p.count};
    }
    int sides(const Polygon& plane, const Polygon& poly) const;
    bool projections_overlap(const Polygon& p, const Polygon& q) const;
    bool separated_by_edges_of(const Polygon& p, const Polygon& q) const;
    Step examine(uint32_t p, uint32_t& q_out) const;
    /// Once the cuts are spent: every polygon left painted in list order (farthest first).
    void paint_rest();
    /// Tests 3–5 and the decision for a Q whose extents overlap P's: nullopt when Q cannot
    /// hide P (the scan goes on), else the step.
    std::optional<Step> compare(uint32_t p_id, uint32_t q_id, uint32_t& q_out) const;
    /// Whether P's neighbours come cheaper from the grid than from the list: its box covers
    /// few of the grid's cells (a polygon over most of the image is compared with every other
    /// anyway), and no trace wants every comparison.
    bool grid_pays(const Polygon& p) const;
    /// The alive Q that may overlap P (depth and extents), from the grid, in list order.
    void grid_candidates(uint32_t p_id) const;
    static ScreenBox box_of(const Polygon& p) { return {p.x_min, p.y_min, p.x_max, p.y_max}; }
    void add_polygon(uint32_t first, uint32_t source, double a, double b, double c);
    /// Cuts polygon `id` where `offset` changes sign: along the plane or an edge line of
    /// polygon `by`, or halved (`cut`, for the trace).
    template <class OffsetFn>
    void split(uint32_t id, OffsetFn&& offset, uint32_t by, DepthSortTrace::Cut cut);
    void retire(uint32_t id);
    bool find_cycle_cut(uint32_t q, uint32_t& cut, uint32_t& by) const;
    /// Cuts polygon `id` along the line of the first edge of `by` whose line crosses it;
    /// false when none does.
    bool split_by_edge_line(uint32_t id, uint32_t by);
    /// Breaks the cycle through P and Q where neither's plane cuts the other polygon.
    void cut_cycle(uint32_t p, uint32_t q);

    std::vector<PolygonVertex> m_vertices;
    std::vector<Polygon> m_polygons;
    std::vector<uint32_t> m_list;  ///< polygon ids by descending z_max (retired ones stay, flagged)
    std::vector<uint8_t> m_retired;
    std::vector<uint8_t> m_marked;  ///< on m_chain: moved ahead of the polygon below it
    std::vector<uint32_t> m_chain;  ///< the current P on top; each waits for the one above it
    std::vector<uint32_t> m_order;  ///< painting order
    std::vector<PolygonVertex> m_front, m_back;  ///< split scratch
    size_t m_head = 0;                           ///< m_list before m_head is all retired
    size_t m_alive = 0;                          ///< polygons neither painted nor split
    int64_t m_split_budget = 0;
    mutable int64_t m_work_budget = 0;  ///< polygons left to look at (k_work_base)
    DepthSortTrace* m_trace = nullptr;
    BoxGrid m_grid;  ///< every polygon's screen box, pieces added as they are cut
    mutable std::vector<uint32_t> m_candidates;  ///< grid_candidates' answer
    mutable std::vector<uint32_t> m_stamp;       ///< per polygon: the query that saw it last
    mutable uint32_t m_query = 0;

  public:
    mutable DepthSortCounts counts;

  private:
    void note(DepthSortTrace::Step step) const {
        if (m_trace) m_trace->steps.push_back(step);
    }
    void note_compare(uint32_t p, uint32_t q, DepthSortTrace::Settled how) const {
        if (m_trace) note({DepthSortTrace::Kind::compare, p, q, how});
    }
};

bool list_before(const Polygon& p, uint32_t p_id, const Polygon& q, uint32_t q_id) {
    return p.z_max != q.z_max ? p.z_max > q.z_max : p_id < q_id;
}

DepthSorter::DepthSorter(std::span<const ScreenTriangle> triangles, DepthSortTrace* trace)
    : m_trace(trace) {
    for (size_t t = 0; t < triangles.size(); ++t) {
        if (t % 65536 == 0) throw_if_cancelled();  // SIGINT, Ctrl-C in Python
        const auto& v = triangles[t].v;
        const PolygonVertex p0{v[0].position.x, v[0].position.y, v[0].position.z};
        const PolygonVertex p1{v[1].position.x, v[1].position.y, v[1].position.z};
        const PolygonVertex p2{v[2].position.x, v[2].position.y, v[2].position.z};
        const double area2 = signed_area2(p0, p1, p2);
        if (!std::isfinite(area2) || area2 == 0 || !std::isfinite(p0.z + p1.z + p2.z)) continue;
        // the triangle's plane, z affine in (x, y) after projection
        const double a = ((p1.z - p0.z) * (p2.y - p0.y) - (p2.z - p0.z) * (p1.y - p0.y)) / area2;
        const double b = ((p2.z - p0.z) * (p1.x - p0.x) - (p1.z - p0.z) * (p2.x - p0.x)) / area2;
        const auto first = static_cast<uint32_t>(m_vertices.size());
        m_vertices.insert(m_vertices.end(), {p0, p1, p2});
        add_polygon(first, static_cast<uint32_t>(t), a, b, p0.z - a * p0.x - b * p0.y);
    }
    m_list.resize(m_polygons.size());
    for (uint32_t i = 0; i < m_list.size(); ++i) m_list[i] = i;
    // sort by farthest depth (Fig 4.6)
    std::sort(m_list.begin(), m_list.end(), [&](uint32_t p, uint32_t q) {
        return list_before(m_polygons[p], p, m_polygons[q], q);
    });
    if (m_trace) m_trace->sorted = m_list;
    // The screen grid of candidate pairs: about four polygons per cell.
    ScreenBox bounds{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (const Polygon& p : m_polygons)
        bounds = {std::min(bounds.x0, p.x_min), std::min(bounds.y0, p.y_min),
                  std::max(bounds.x1, p.x_max), std::max(bounds.y1, p.y_max)};
    if (!m_polygons.empty()) {
        m_grid = BoxGrid(bounds, m_polygons.size() / 4);
        for (uint32_t i = 0; i < m_polygons.size(); ++i) m_grid.insert(i, box_of(m_polygons[i]));
        throw_if_cancelled();
    }
    // every interpenetrating pair needs a cut and pieces can be cut again; past this budget the
    // order is accepted as it is, so the sort always ends. A tangle of polygons that pierce
    // one another everywhere (random triangles across one volume) needs cuts quadratic in
    // their number: the budget grows linearly, and running out is reported (counts.gave_up).
    const auto n = static_cast<int64_t>(m_polygons.size());
    m_split_budget = std::min<int64_t>(
                         8 * n * n, std::max<int64_t>(k_splits_per_polygon * n, int64_t{1} << 22)) +
                     1024;
    m_work_budget = (m_trace ? k_work_base_traced : k_work_base) + k_work_per_polygon * n;
}

/// Makes a polygon of the pooled vertices from `first` to the end of the pool.
void DepthSorter::add_polygon(uint32_t first, uint32_t source, double a, double b, double c) {
    Polygon p;
    p.first = first;
    p.count = static_cast<uint32_t>(m_vertices.size()) - p.first;
    p.source = source;
    p.a = a;
    p.b = b;
    p.c = c;
    p.x_min = p.y_min = p.z_min = INFINITY;
    p.x_max = p.y_max = p.z_max = -INFINITY;
    for (const PolygonVertex& v : vertices(p)) {
        p.x_min = std::min(p.x_min, v.x), p.x_max = std::max(p.x_max, v.x);
        p.y_min = std::min(p.y_min, v.y), p.y_max = std::max(p.y_max, v.y);
        p.z_min = std::min(p.z_min, v.z), p.z_max = std::max(p.z_max, v.z);
    }
    m_polygons.push_back(p);
    if (m_trace) m_trace->source.push_back(source);
    ++m_alive;
    m_retired.push_back(0);
    m_marked.push_back(0);
}

/// Signed depth of `v` behind `plane` (> 0: farther from the viewer), with its tolerance.
double plane_offset(const Polygon& plane, const PolygonVertex& v, double& tolerance) {
    const double ax = plane.a * v.x, by = plane.b * v.y;
    tolerance = k_side_epsilon * (1 + std::abs(ax) + std::abs(by) + std::abs(plane.c));
    return v.z - (ax + by + plane.c);
}

int DepthSorter::sides(const Polygon& plane, const Polygon& poly) const {
    int bits = k_on_plane;
    for (const PolygonVertex& v : vertices(poly)) {
        double tolerance = 0;
        const double d = plane_offset(plane, v, tolerance);
        if (d > tolerance) bits |= k_behind;
        if (d < -tolerance) bits |= k_in_front;
    }
    return bits;
}

/// Separating axis test along the edge normals of `p` (touching counts as separated: a pixel
/// centre on a shared boundary is covered by one polygon only, so their order does not matter).
bool DepthSorter::separated_by_edges_of(const Polygon& p, const Polygon& q) const {
    const auto pv = vertices(p), qv = vertices(q);
    for (size_t k = 0; k < pv.size(); ++k) {
        const PolygonVertex& s = pv[k];
        const PolygonVertex& e = pv[(k + 1) % pv.size()];
        const double nx = s.y - e.y, ny = e.x - s.x;
        if (nx == 0 && ny == 0) continue;
        double p_lo = INFINITY, p_hi = -INFINITY, q_lo = INFINITY, q_hi = -INFINITY;
        for (const PolygonVertex& v : pv) {
            const double t = nx * v.x + ny * v.y;
            p_lo = std::min(p_lo, t), p_hi = std::max(p_hi, t);
        }
        for (const PolygonVertex& v : qv) {
            const double t = nx * v.x + ny * v.y;
            q_lo = std::min(q_lo, t), q_hi = std::max(q_hi, t);
        }
        const double tolerance =
            k_side_epsilon * (std::abs(nx) + std::abs(ny) + std::abs(p_lo) + std::abs(p_hi));
        if (p_hi <= q_lo + tolerance || q_hi <= p_lo + tolerance) return true;
    }
    return false;
}

bool DepthSorter::projections_overlap(const Polygon& p, const Polygon& q) const {
    return !separated_by_edges_of(p, q) && !separated_by_edges_of(q, p);
}

bool DepthSorter::grid_pays(const Polygon& p) const {
    return !m_trace && 4 * m_grid.cells_covered(box_of(p)) < m_grid.cell_count();
}

void DepthSorter::grid_candidates(uint32_t p_id) const {
    const Polygon& p = m_polygons[p_id];
    m_candidates.clear();
    m_stamp.resize(m_polygons.size(), 0);
    ++m_query;
    m_grid.for_each_in_box(box_of(p), [&](uint32_t q_id) {
        if (m_stamp[q_id] == m_query) return;
        m_stamp[q_id] = m_query;
        const Polygon& q = m_polygons[q_id];
        // what the list scan skips: itself, the painted or cut, Q wholly in front (depth), and
        // tests 1 and 2 (the x or y extents do not overlap)
        if (q_id == p_id || m_retired[q_id] || q.z_max <= p.z_min) return;
        if (p.x_max <= q.x_min || q.x_max <= p.x_min || p.y_max <= q.y_min || q.y_max <= p.y_min)
            return;
        m_candidates.push_back(q_id);
    });
    std::sort(m_candidates.begin(), m_candidates.end(), [&](uint32_t a, uint32_t b) {
        return list_before(m_polygons[a], a, m_polygons[b], b);
    });
}

/// Newell, Newell & Sancha 1972: may P be painted now, before every Q it shares depths with?
/// The Q are met in list order, from the list itself or, the same ones, from the screen grid.
Step DepthSorter::examine(uint32_t p_id, uint32_t& q_out) const {
    const Polygon& p = m_polygons[p_id];
    if (grid_pays(p)) {
        grid_candidates(p_id);
        m_work_budget -= static_cast<int64_t>(m_candidates.size()) + 1;
        for (const uint32_t q_id : m_candidates)
            if (const std::optional<Step> step = compare(p_id, q_id, q_out)) return *step;
        return Step::paint;
    }
    for (size_t k = m_head; k < m_list.size(); ++k) {
        const uint32_t q_id = m_list[k];
        const Polygon& q = m_polygons[q_id];
        // the list is sorted by z_max: from here on every Q lies entirely in front of P
        if (q.z_max <= p.z_min) break;
        --m_work_budget;
        if (q_id == p_id || m_retired[q_id]) continue;
        using Settled = DepthSortTrace::Settled;
        // test 1, 2: the x or the y extents do not overlap
        if (p.x_max <= q.x_min || q.x_max <= p.x_min) {
            note_compare(p_id, q_id, Settled::x_extents);
            continue;
        }
        if (p.y_max <= q.y_min || q.y_max <= p.y_min) {
            note_compare(p_id, q_id, Settled::y_extents);
            continue;
        }
        if (const std::optional<Step> step = compare(p_id, q_id, q_out)) return *step;
    }
    return Step::paint;
}

std::optional<Step> DepthSorter::compare(uint32_t p_id, uint32_t q_id, uint32_t& q_out) const {
    const Polygon &p = m_polygons[p_id], &q = m_polygons[q_id];
    using Settled = DepthSortTrace::Settled;
    // test 3: P entirely behind Q's plane (on the far side from the viewer)
    const int p_wrt_q = sides(q, p);
    if (!(p_wrt_q & k_in_front)) {
        note_compare(p_id, q_id, Settled::p_behind_q);
        return std::nullopt;
    }
    // test 4: Q entirely in front of P's plane
    const int q_wrt_p = sides(p, q);
    if (!(q_wrt_p & k_behind)) {
        note_compare(p_id, q_id, Settled::q_in_front);
        return std::nullopt;
    }
    // test 5: the projections do not overlap
    if (!projections_overlap(p, q)) {
        note_compare(p_id, q_id, Settled::no_overlap);
        return std::nullopt;
    }
    // Q may hide part of P. Can Q go first (tests 3, 4 with P and Q swapped)?
    note_compare(p_id, q_id, Settled::q_may_hide);
    q_out = q_id;
    const bool q_first = !(q_wrt_p & k_in_front) || !(p_wrt_q & k_behind);
    if (!q_first) return Step::split_q_by_p;  // interpenetration (Fig 4.9b): they straddle
    if (!m_marked[q_id]) return Step::move_q;
    // Q already waits above P: cyclic overlap (Fig 4.9a); cut the cycle
    if (q_wrt_p == k_straddles) return Step::split_q_by_p;
    if (p_wrt_q == k_straddles) return Step::split_p_by_q;
    return Step::bisect_p;
}

/// A member of the cycle from marked Q up the chain to P that straddles the plane of another
/// member whose projection it overlaps.
bool DepthSorter::find_cycle_cut(uint32_t q, uint32_t& cut, uint32_t& by) const {
    const auto from = std::find(m_chain.begin(), m_chain.end(), q);
    const auto members = static_cast<int64_t>(m_chain.end() - from);
    m_work_budget -= members * members;
    for (auto x = from; x != m_chain.end(); ++x)
        for (auto y = from; y != m_chain.end(); ++y) {
            if (x == y) continue;
            const Polygon& px = m_polygons[*x];
            const Polygon& py = m_polygons[*y];
            if (px.x_max <= py.x_min || py.x_max <= px.x_min) continue;
            if (px.y_max <= py.y_min || py.y_max <= px.y_min) continue;
            if (sides(px, py) != k_straddles || !projections_overlap(px, py)) continue;
            cut = *y;
            by = *x;
            return true;
        }
    return false;
}

bool DepthSorter::split_by_edge_line(uint32_t id, uint32_t by) {
    const auto bv = vertices(m_polygons[by]);
    for (size_t k = 0; k < bv.size(); ++k) {
        const PolygonVertex u = bv[k], w = bv[(k + 1) % bv.size()];
        // signed distance (times the edge length) of v from the line through u and w
        auto offset = [u, w](const PolygonVertex& v, double& tolerance) {
            const double ex = w.x - u.x, ey = w.y - u.y;
            tolerance = k_side_epsilon * (1 + std::abs(ex) + std::abs(ey)) *
                        (1 + std::abs(v.x - u.x) + std::abs(v.y - u.y));
            return ex * (v.y - u.y) - ey * (v.x - u.x);
        };
        bool below = false, above = false;
        for (const PolygonVertex& v : vertices(m_polygons[id])) {
            double tolerance = 0;
            const double d = offset(v, tolerance);
            below |= d < -tolerance;
            above |= d > tolerance;
        }
        if (below && above) {
            split(id, offset, by, DepthSortTrace::Cut::by_edge_line);
            return true;
        }
    }
    return false;
}

void DepthSorter::retire(uint32_t id) {
    m_retired[id] = 1;
    --m_alive;
    m_marked[id] = 0;
    std::erase(m_chain, id);
}

/// Cuts polygon `id` where `offset` changes sign (Sutherland-Hodgman against both half-spaces),
/// retires it and inserts the pieces into the list. Cut vertices are computed once and shared,
/// so the pieces meet without cracks.
template <class OffsetFn>
void DepthSorter::split(uint32_t id, OffsetFn&& offset, uint32_t by, DepthSortTrace::Cut cut) {
    --m_split_budget;
    ++counts.splits;
    m_work_budget -= static_cast<int64_t>(m_list.size() - m_head) / 16 + 1;  // the insertions
    const size_t before = m_polygons.size();
    const Polygon parent = m_polygons[id];
    m_front.clear();
    m_back.clear();
    const auto pv = vertices(parent);
    auto side = [&](const PolygonVertex& v, double& d) {
        double tolerance = 0;
        d = offset(v, tolerance);
        return d > tolerance ? 1 : (d < -tolerance ? -1 : 0);
    };
    for (size_t k = 0; k < pv.size(); ++k) {
        const PolygonVertex v = pv[k], w = pv[(k + 1) % pv.size()];
        double dv = 0, dw = 0;
        const int sv = side(v, dv), sw = side(w, dw);
        if (sv >= 0) m_back.push_back(v);
        if (sv <= 0) m_front.push_back(v);
        if (sv * sw < 0) {
            const double t = dv / (dv - dw);
            const PolygonVertex cut{v.x + t * (w.x - v.x), v.y + t * (w.y - v.y),
                                    v.z + t * (w.z - v.z)};
            m_back.push_back(cut);
            m_front.push_back(cut);
        }
    }
    retire(id);
    for (const std::vector<PolygonVertex>* piece : {&m_back, &m_front}) {
        if (piece->size() < 3) continue;
        double area2 = 0;
        for (size_t k = 1; k + 1 < piece->size(); ++k)
            area2 += signed_area2((*piece)[0], (*piece)[k], (*piece)[k + 1]);
        if (std::abs(area2) < k_min_area2) continue;
        const auto first = static_cast<uint32_t>(m_vertices.size());
        m_vertices.insert(m_vertices.end(), piece->begin(), piece->end());
        add_polygon(first, parent.source, parent.a, parent.b, parent.c);
        // re-insert by farthest depth
        const uint32_t new_id = static_cast<uint32_t>(m_polygons.size() - 1);
        const auto at = std::upper_bound(m_list.begin() + static_cast<std::ptrdiff_t>(m_head),
                                         m_list.end(), new_id, [&](uint32_t n, uint32_t e) {
                                             return list_before(m_polygons[n], n, m_polygons[e], e);
                                         });
        m_list.insert(at, new_id);
        m_grid.insert(new_id, box_of(m_polygons[new_id]));
    }
    note({DepthSortTrace::Kind::split, id, by, DepthSortTrace::Settled::q_may_hide, cut,
          static_cast<uint32_t>(m_polygons.size() - before)});
}

void DepthSorter::cut_cycle(uint32_t p, uint32_t q) {
    // Cut the cycle where another of its members straddles the plane of one it overlaps.
    uint32_t cut = 0, by = 0;
    if (find_cycle_cut(q, cut, by)) {
        split(
            cut,
            [&](const PolygonVertex& v, double& tol) {
                return plane_offset(m_polygons[by], v, tol);
            },
            by, DepthSortTrace::Cut::by_plane);
        return;
    }
    // No plane cuts it: cut P (or Q) along the screen-space line of an edge of the other. The
    // pieces outside the other's projection no longer overlap it, and the piece inside lies
    // wholly in front of or behind it, so the cycle breaks. (Halving instead keeps a piece on
    // the other's boundary forever.)
    if (split_by_edge_line(p, q) || split_by_edge_line(q, p)) return;
    // last resort: halve P across its longer extent
    const Polygon& pp = m_polygons[p];
    const bool along_x = pp.x_max - pp.x_min >= pp.y_max - pp.y_min;
    const double mid = along_x ? 0.5 * (pp.x_min + pp.x_max) : 0.5 * (pp.y_min + pp.y_max);
    split(
        p,
        [&](const PolygonVertex& v, double& tol) {
            tol = 0;
            return (along_x ? v.x : v.y) - mid;
        },
        q, DepthSortTrace::Cut::halved);
}

void DepthSorter::paint_rest() {
    counts.gave_up = true;
    for (size_t k = m_head; k < m_list.size(); ++k)
        if (!m_retired[m_list[k]]) {
            note({DepthSortTrace::Kind::paint, m_list[k], m_list[k]});
            m_order.push_back(m_list[k]);
            m_retired[m_list[k]] = 1;
        }
    m_chain.clear();
}

void DepthSorter::sort() {
    for (uint32_t iteration = 1;; ++iteration) {
        if (iteration % 256 == 0) throw_if_cancelled();  // SIGINT, Ctrl-C in Python
        // drop retired entries once they are most of the list, so scans stay short
        if (m_list.size() - m_head > 2 * m_alive + 64) {
            std::erase_if(m_list, [&](uint32_t id) { return m_retired[id] != 0; });
            m_head = 0;
        }
        if (m_chain.empty()) {
            while (m_head < m_list.size() && m_retired[m_list[m_head]]) ++m_head;
            if (m_head == m_list.size()) return;
            m_chain.push_back(m_list[m_head]);
            m_marked[m_list[m_head]] = 1;
        }
        if (m_split_budget <= 0 || m_work_budget <= 0) return paint_rest();
        const uint32_t p = m_chain.back();
        uint32_t q = 0;
        Step step = examine(p, q);
        if (step != Step::paint && step != Step::move_q &&
            (m_split_budget <= 0 || m_work_budget <= 0)) {
            step = Step::paint;
            counts.gave_up = true;
        }
        switch (step) {
            case Step::paint:
                note({DepthSortTrace::Kind::paint, p, p});
                m_order.push_back(p);
                retire(p);
                break;
            case Step::move_q:  // reorder: Q is painted before P
                note({DepthSortTrace::Kind::reorder, p, q});
                m_chain.push_back(q);
                m_marked[q] = 1;
                break;
            case Step::split_q_by_p:
                split(
                    q,
                    [&](const PolygonVertex& v, double& tol) {
                        return plane_offset(m_polygons[p], v, tol);
                    },
                    p, DepthSortTrace::Cut::by_plane);
                break;
            case Step::split_p_by_q:
                split(
                    p,
                    [&](const PolygonVertex& v, double& tol) {
                        return plane_offset(m_polygons[q], v, tol);
                    },
                    q, DepthSortTrace::Cut::by_plane);
                break;
            case Step::bisect_p:
                cut_cycle(p, q);
                break;
        }
    }
}

void DepthSorter::paint(VisibilityBuffer& out, uint32_t limit) const {
    if (m_trace) {
        m_trace->painted = m_order;
        m_trace->visible_paint.assign(out.triangle.size(), UINT32_MAX);
        m_trace->paint_count.assign(out.triangle.size(), 0);
    }
    counts.polygons = m_order.size();
    const auto painted = static_cast<uint32_t>(std::min<size_t>(m_order.size(), limit));
    // Painter's algorithm (Fig 4.6): later (nearer) polygons overwrite. Bands of rows are
    // independent (each pixel lies in one), so they are painted at the same time, each band
    // taking the first `painted` polygons of the order that reach it, in that order: every pixel
    // ends as one painter going down the whole order would leave it.
    const int bands = (out.height + k_paint_band_rows - 1) / k_paint_band_rows;
    std::vector<uint32_t> band_begin(static_cast<size_t>(bands) + 1, 0);
    auto band_range = [&](const Polygon& p) {
        const PixelRange rows = centre_range(p.y_min, p.y_max, out.height);
        return rows.empty() ? std::pair{0, 0}
                            : std::pair{rows.begin / k_paint_band_rows,
                                        (rows.end - 1) / k_paint_band_rows + 1};
    };
    for (uint32_t k = 0; k < painted; ++k) {
        const auto [b0, b1] = band_range(m_polygons[m_order[k]]);
        for (int b = b0; b < b1; ++b) ++band_begin[b + 1];
    }
    for (int b = 0; b < bands; ++b) band_begin[b + 1] += band_begin[b];
    std::vector<uint32_t> in_band(band_begin[bands]);  // positions in the order, band by band
    std::vector<uint32_t> fill(band_begin.begin(), band_begin.end() - 1);
    for (uint32_t k = 0; k < painted; ++k) {
        const auto [b0, b1] = band_range(m_polygons[m_order[k]]);
        for (int b = b0; b < b1; ++b) in_band[fill[b]++] = k;
    }
    std::vector<uint64_t> band_paints(static_cast<size_t>(bands), 0);
    hikari::parallel_for(0, bands, [&](int b) {
        const int row0 = b * k_paint_band_rows;
        const int row1 = std::min(out.height, row0 + k_paint_band_rows);
        uint64_t paints = 0;
        for (uint32_t e = band_begin[b]; e < band_begin[b + 1]; ++e) {
            const uint32_t k = in_band[e];
            const Polygon& p = m_polygons[m_order[k]];
            fill_convex_polygon_rows(
                vertices(p), out.width, out.height, row0, row1, [&](int i, int j) {
                    const size_t pixel = static_cast<size_t>(j) * out.width + i;
                    out.triangle[pixel] = p.source;
                    ++paints;
                    if (m_trace) {
                        m_trace->visible_paint[pixel] = k;
                        ++m_trace->paint_count[pixel];
                    }
                });
        }
        band_paints[b] = paints;
    });
    for (const uint64_t n : band_paints) counts.paints += n;
}

VisibilityBuffer empty_buffer(int width, int height) {
    VisibilityBuffer out;
    out.width = std::max(width, 0);
    out.height = std::max(height, 0);
    out.triangle.assign(static_cast<size_t>(out.width) * out.height, k_no_triangle);
    return out;
}

/// Per triangle, the polygon (model face) it belongs to, named by one of its triangles: triangles
/// sharing an edge that is not the face's own (a diagonal of its triangulation) are one polygon.
std::vector<uint32_t> polygons_of(const TriangleSet& triangles) {
    std::vector<uint32_t> parent(triangles.size());
    for (uint32_t t = 0; t < parent.size(); ++t) parent[t] = t;
    const auto root = [&](uint32_t t) {
        while (parent[t] != t) t = parent[t] = parent[parent[t]];
        return t;
    };
    std::unordered_map<uint64_t, uint32_t> diagonal;  // vertex pair -> first triangle on it
    for (uint32_t t = 0; t < triangles.edge_flags.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            if ((triangles.edge_flags[t] >> k) & 1) continue;
            const uint32_t a = triangles.indices[t][k], b = triangles.indices[t][(k + 1) % 3];
            const uint64_t key = (uint64_t{std::min(a, b)} << 32) | std::max(a, b);
            const auto [it, first] = diagonal.emplace(key, t);
            if (!first) parent[root(t)] = root(it->second);
        }
    for (uint32_t t = 0; t < parent.size(); ++t) parent[t] = root(t);
    return parent;
}

}  // namespace

VisibilityBuffer depth_sort_visibility(std::span<const ScreenTriangle> triangles, int width,
                                       int height) {
    VisibilityBuffer out = empty_buffer(width, height);
    if (out.triangle.empty()) return out;
    DepthSorter sorter(triangles);
    sorter.sort();
    sorter.paint(out);
    return out;
}

VisibilityBuffer depth_sort_visibility_counted(std::span<const ScreenTriangle> triangles, int width,
                                               int height, DepthSortCounts& counts,
                                               uint32_t paint_limit) {
    VisibilityBuffer out = empty_buffer(width, height);
    if (out.triangle.empty()) return out;
    DepthSorter sorter(triangles);
    sorter.sort();
    sorter.paint(out, paint_limit);
    counts = sorter.counts;
    return out;
}

VisibilityBuffer depth_sort_visibility_traced(std::span<const ScreenTriangle> triangles, int width,
                                              int height, DepthSortTrace& trace) {
    trace = {};
    VisibilityBuffer out = empty_buffer(width, height);
    if (out.triangle.empty()) return out;
    DepthSorter sorter(triangles, &trace);
    sorter.sort();
    sorter.paint(out);
    return out;
}

VisibilityBuffer depth_sort_naive_visibility(std::span<const ScreenTriangle> triangles, int width,
                                             int height, std::span<const double> polygon_depth) {
    VisibilityBuffer out = empty_buffer(width, height);
    if (out.triangle.empty()) return out;
    // Fig 4.7: priority by centroid depth alone, farthest first. Without polygon depths the
    // screen z key (−near / w, larger for farther) of each triangle's corners stands in.
    std::vector<std::pair<double, uint32_t>> order;
    order.reserve(triangles.size());
    for (uint32_t t = 0; t < triangles.size(); ++t) {
        const auto& v = triangles[t].v;
        const double key = polygon_depth.empty()
                               ? (double{v[0].position.z} + v[1].position.z + v[2].position.z) / 3.0
                               : polygon_depth[triangles[t].source];
        if (std::isfinite(key)) order.emplace_back(key, t);
    }
    std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first > b.first : a.second < b.second;
    });
    for (const auto& entry : order) {
        const uint32_t t = entry.second;
        PolygonVertex tri[3];
        for (int k = 0; k < 3; ++k) {
            const Vec3 p = triangles[t].v[k].position;
            tri[k] = {p.x, p.y, p.z};
        }
        if (signed_area2(tri[0], tri[1], tri[2]) == 0) continue;
        fill_convex_polygon(
            std::span<const PolygonVertex>(tri, 3), out.width, out.height,
            [&](int i, int j) { out.triangle[static_cast<size_t>(j) * out.width + i] = t; });
    }
    return out;
}

Framebuffer render_depth_sort(const Scene& scene, Film film, const RenderSettings& settings,
                              const RasterSettings& raster) {
    return render_raster(
        scene, std::move(film), settings, raster, [&](auto triangles, int width, int height) {
            DepthSortCounts counts;
            const uint32_t limit =
                raster.paint_steps > 0 ? static_cast<uint32_t>(raster.paint_steps) : UINT32_MAX;
            VisibilityBuffer vis =
                depth_sort_visibility_counted(triangles, width, height, counts, limit);
            if (settings.stats) {
                settings.stats->raster_fragments += counts.paints;
                settings.stats->depth_sort_splits += counts.splits;
                // The longest order of any sample (supersampling paints one order per sample).
                uint64_t longest = settings.stats->depth_sort_polygons.load();
                while (counts.polygons > longest &&
                       !settings.stats->depth_sort_polygons.compare_exchange_weak(
                           longest, counts.polygons)) {
                }
                if (counts.gave_up) settings.stats->depth_sort_gave_up = 1;
            }
            return vis;
        });
}

std::vector<double> polygon_centroid_depths(const TriangleSet& triangles,
                                            const Mat4& view_from_world) {
    const size_t n = triangles.size();
    const std::vector<uint32_t> polygon = polygons_of(triangles);
    // Area-weighted sums of the triangles' centroid depths: depth is affine in view space, so
    // the polygon centroid's depth is the area-weighted mean of its triangles'.
    std::vector<double> area(n, 0.0), weighted(n, 0.0), plain(n, 0.0), count(n, 0.0);
    std::vector<double> depth_of(n);
    for (size_t t = 0; t < n; ++t) {
        const auto& idx = triangles.indices[t];
        const Vec3 a = triangles.positions[idx[0]], b = triangles.positions[idx[1]],
                   c = triangles.positions[idx[2]];
        // View space looks down −z: the eye-space depth of a point is −z_view.
        const double d = -transform_point(view_from_world, (a + b + c) / 3.0f).z;
        const double w = 0.5 * length(cross(b - a, c - a));
        area[polygon[t]] += w;
        weighted[polygon[t]] += w * d;
        plain[polygon[t]] += d;
        count[polygon[t]] += 1;
    }
    for (size_t t = 0; t < n; ++t) {
        const uint32_t p = polygon[t];
        depth_of[t] = area[p] > 0 ? weighted[p] / area[p] : plain[p] / count[p];
    }
    return depth_of;
}

Framebuffer render_depth_sort_naive(const Scene& scene, Film film, const RenderSettings& settings,
                                    const RasterSettings& raster) {
    const ProjectedScene ps = project_scene(scene, raster);
    const std::vector<double> depths =
        polygon_centroid_depths(ps.scene.triangles, ps.view.view_from_world);
    const VisibilityBuffer vis =
        depth_sort_naive_visibility(std::span<const ScreenTriangle>(ps.triangles),
                                    scene.camera.width, scene.camera.height, depths);
    if (settings.stats) report_raster_stats(ps, vis, *settings.stats);
    return shade_visibility(scene, ps, vis, std::move(film), settings, raster);
}

}  // namespace hikari
