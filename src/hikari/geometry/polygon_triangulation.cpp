#include "hikari/geometry/polygon_triangulation.h"

#include <cmath>

namespace hikari {
namespace {

/// A polygon's corners in 2D, in the plane of its normal, counter-clockwise seen from the front.
struct PlanarPolygon {
    std::vector<double> x, y;

    double turn(uint32_t a, uint32_t b, uint32_t c) const {
        return (x[b] - x[a]) * (y[c] - y[b]) - (y[b] - y[a]) * (x[c] - x[b]);
    }
    /// True when p lies inside or on triangle (a, b, c), which is counter-clockwise.
    bool inside(uint32_t p, uint32_t a, uint32_t b, uint32_t c) const {
        return turn(a, b, p) >= 0.0 && turn(b, c, p) >= 0.0 && turn(c, a, p) >= 0.0;
    }
};

/// Newell's normal: exact for planar polygons, a robust average for nearly planar ones, and its
/// length is twice the area.
Vec3 newell_normal(std::span<const Vec3> p) {
    double nx = 0, ny = 0, nz = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        const Vec3 a = p[i], b = p[(i + 1) % p.size()];
        nx += (double(a.y) - b.y) * (double(a.z) + b.z);
        ny += (double(a.z) - b.z) * (double(a.x) + b.x);
        nz += (double(a.x) - b.x) * (double(a.y) + b.y);
    }
    return {float(nx), float(ny), float(nz)};
}

/// Drops the normal's largest axis; swaps the two kept ones where needed so the polygon stays
/// counter-clockwise in 2D.
PlanarPolygon project(std::span<const Vec3> p, Vec3 n) {
    const float ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
    const int drop = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
    int u = (drop + 1) % 3, v = (drop + 2) % 3;
    if (n[drop] < 0.0f) std::swap(u, v);
    PlanarPolygon out;
    out.x.resize(p.size());
    out.y.resize(p.size());
    for (size_t i = 0; i < p.size(); ++i) {
        out.x[i] = p[i][u];
        out.y[i] = p[i][v];
    }
    return out;
}

/// True when every corner turns left (or goes straight) and the turns add up to one revolution:
/// a star whose corners all turn left winds twice and is not convex.
bool is_convex(const PlanarPolygon& q) {
    const auto n = static_cast<uint32_t>(q.x.size());
    double total = 0.0;
    for (uint32_t i = 0; i < n; ++i) {
        const uint32_t a = (i + n - 1) % n, c = (i + 1) % n;
        const double t = q.turn(a, i, c);
        if (t < 0.0) return false;
        const double dot =
            (q.x[i] - q.x[a]) * (q.x[c] - q.x[i]) + (q.y[i] - q.y[a]) * (q.y[c] - q.y[i]);
        total += std::atan2(t, dot);
    }
    return std::abs(total - 2.0 * M_PI) < 1e-3;
}

/// True when two edges that share no corner cross or touch (O(n²), so only for modest n).
bool edges_cross(const PlanarPolygon& q) {
    const auto n = static_cast<uint32_t>(q.x.size());
    auto sign = [&](uint32_t a, uint32_t b, uint32_t c) {
        const double t = q.turn(a, b, c);
        return (t > 0.0) - (t < 0.0);
    };
    for (uint32_t i = 0; i < n; ++i) {
        const uint32_t i1 = (i + 1) % n;
        for (uint32_t j = i + 2; j < n; ++j) {
            const uint32_t j1 = (j + 1) % n;
            if (j1 == i) continue;  // the edge before i shares corner i
            if (sign(i, i1, j) * sign(i, i1, j1) < 0 && sign(j, j1, i) * sign(j, j1, i1) < 0)
                return true;
        }
    }
    return false;
}

uint8_t outline_flags(uint32_t a, uint32_t b, uint32_t c, uint32_t n) {
    auto next = [n](uint32_t i) { return (i + 1) % n; };
    return static_cast<uint8_t>((next(a) == b ? 1 : 0) | (next(b) == c ? 2 : 0) |
                                (next(c) == a ? 4 : 0));
}

void fan(uint32_t n, std::vector<PolygonTriangle>& out) {
    for (uint32_t k = 1; k + 1 < n; ++k)
        out.push_back({{0, k, k + 1}, outline_flags(0, k, k + 1, n)});
}

/// Ear clipping over a circular list of the remaining corners. Only reflex corners can lie
/// inside an ear, so only they are tested. When no ear is found (crossing edges, or rounding on a
/// nearly degenerate outline), the corner turning most to the left is cut anyway so the polygon
/// still becomes n - 2 triangles.
void clip_ears(const PlanarPolygon& q, std::vector<PolygonTriangle>& out) {
    const auto n = static_cast<uint32_t>(q.x.size());
    std::vector<uint32_t> prev(n), next(n);
    for (uint32_t i = 0; i < n; ++i) {
        prev[i] = (i + n - 1) % n;
        next[i] = (i + 1) % n;
    }
    auto is_ear = [&](uint32_t i) {
        const uint32_t a = prev[i], c = next[i];
        if (!(q.turn(a, i, c) > 0.0)) return false;
        for (uint32_t p = next[c]; p != a; p = next[p]) {
            if (q.turn(prev[p], p, next[p]) > 0.0) continue;  // convex corners cannot be inside
            const bool same_point = (q.x[p] == q.x[a] && q.y[p] == q.y[a]) ||
                                    (q.x[p] == q.x[i] && q.y[p] == q.y[i]) ||
                                    (q.x[p] == q.x[c] && q.y[p] == q.y[c]);
            if (!same_point && q.inside(p, a, i, c)) return false;
        }
        return true;
    };
    uint32_t remaining = n, i = 0;
    while (remaining > 3) {
        uint32_t cut = n;
        for (uint32_t k = 0, j = i; k < remaining; ++k, j = next[j]) {
            if (is_ear(j)) {
                cut = j;
                break;
            }
        }
        if (cut == n) {
            double best = -INFINITY;
            for (uint32_t k = 0, j = i; k < remaining; ++k, j = next[j]) {
                const double t = q.turn(prev[j], j, next[j]);
                if (t > best) best = t, cut = j;
            }
        }
        const uint32_t a = prev[cut], c = next[cut];
        out.push_back({{a, cut, c}, outline_flags(a, cut, c, n)});
        next[a] = c;
        prev[c] = a;
        i = c;
        --remaining;
    }
    const uint32_t a = prev[i], c = next[i];
    out.push_back({{a, i, c}, outline_flags(a, i, c, n)});
}

}  // namespace

PolygonShape triangulate_polygon(std::span<const Vec3> corners, std::vector<PolygonTriangle>& out) {
    const auto n = static_cast<uint32_t>(corners.size());
    if (n < 3) return PolygonShape::Degenerate;
    if (n == 3) {
        out.push_back({{0, 1, 2}, 7});
        return PolygonShape::Convex;
    }
    const Vec3 normal = newell_normal(corners);
    if (!(dot(normal, normal) > 0.0f) || !std::isfinite(dot(normal, normal))) {
        fan(n, out);
        return PolygonShape::Degenerate;
    }
    const PlanarPolygon q = project(corners, normal);
    if (is_convex(q)) {
        fan(n, out);
        return PolygonShape::Convex;
    }
    // The crossing test is quadratic: polygons of thousands of corners are taken as simple.
    const bool crossing = n <= 4096 && edges_cross(q);
    clip_ears(q, out);
    return crossing ? PolygonShape::SelfIntersecting : PolygonShape::Concave;
}

}  // namespace hikari
