#include "hikari/shading/soft_shadows/visible_light.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>

#include "hikari/core/orthonormal_basis.h"
#include "hikari/core/ray.h"

namespace hikari {

namespace {

/// Convex polygons in the light's (a, b) coordinates, one buffer for all.
struct Pieces {
    std::vector<Vec2> corners;
    std::vector<int> starts{0};

    int count() const { return static_cast<int>(starts.size()) - 1; }
    void add(const Vec2* c, int n) {
        corners.insert(corners.end(), c, c + n);
        starts.push_back(static_cast<int>(corners.size()));
    }
    void clear() {
        corners.clear();
        starts.assign(1, 0);
    }
};

/// A line a·x + b·y + c = 0 of the (a, b) plane; inside is where the expression is >= 0.
struct Line2 {
    float a, b, c;
    float at(Vec2 q) const { return a * q.x + b * q.y + c; }
};

/// The line through p and q, positive to its left: the inside of a counter-clockwise polygon
/// with edge p → q.
Line2 left_of(Vec2 p, Vec2 q) {
    return {-(q.y - p.y), q.x - p.x, (q.y - p.y) * p.x - (q.x - p.x) * p.y};
}

/// The part of convex polygon `in` (n corners) where `line` >= 0 (`inside`) and the part where
/// it is < 0 (`outside`), Sutherland–Hodgman style; each output has at most n + 1 corners.
void split(const Vec2* in, int n, const Line2& line, std::vector<Vec2>& inside,
           std::vector<Vec2>& outside) {
    inside.clear();
    outside.clear();
    for (int i = 0; i < n; ++i) {
        const Vec2 p = in[i], q = in[(i + 1) % n];
        const float dp = line.at(p), dq = line.at(q);
        (dp >= 0.0f ? inside : outside).push_back(p);
        if ((dp >= 0.0f) != (dq >= 0.0f)) {
            const float t = dp / (dp - dq);
            const Vec2 x{p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)};
            inside.push_back(x);
            outside.push_back(x);
        }
    }
}

float signed_area(const std::vector<Vec2>& c) {
    float twice = 0.0f;
    for (size_t i = 0; i < c.size(); ++i) {
        const Vec2 p = c[i], q = c[(i + 1) % c.size()];
        twice += p.x * q.y - q.x * p.y;
    }
    return 0.5f * twice;
}

/// The light's plane and (a, b) coordinates, and the side the point is on.
struct LightFrame {
    Vec3 corner, e1, e2;
    Vec3 unit_normal;   ///< toward the point's side
    Vec3 dual1, dual2;  ///< a = dot(y − corner, dual1), b = dot(y − corner, dual2)
    float height = 0;   ///< the point's distance from the light's plane

    Vec3 world(Vec2 ab) const { return corner + ab.x * e1 + ab.y * e2; }
    Vec2 coords(Vec3 y) const { return {dot(y - corner, dual1), dot(y - corner, dual2)}; }
    /// Distance of x from the light's plane, positive on the point's side.
    float above(Vec3 x) const { return dot(x - corner, unit_normal); }
};

/// Clips the convex 3-D polygon `poly` to where dot(m, x) >= d.
void clip3(std::vector<Vec3>& poly, std::vector<Vec3>& scratch, Vec3 m, float d) {
    scratch.clear();
    for (size_t i = 0; i < poly.size(); ++i) {
        const Vec3 p = poly[i], q = poly[(i + 1) % poly.size()];
        const float dp = dot(m, p) - d, dq = dot(m, q) - d;
        if (dp >= 0.0f) scratch.push_back(p);
        if ((dp >= 0.0f) != (dq >= 0.0f)) scratch.push_back(p + (dp / (dp - dq)) * (q - p));
    }
    poly.swap(scratch);
}

/// Removes convex polygon `hole` (counter-clockwise) from every piece: each piece is split by
/// the hole's edge lines; what lies outside an edge stays, what lies inside all of them goes.
void subtract(Pieces& pieces, Pieces& next, const std::vector<Vec2>& hole) {
    Vec2 lo = hole[0], hi = hole[0];
    for (const Vec2 h : hole) {
        lo = {std::min(lo.x, h.x), std::min(lo.y, h.y)};
        hi = {std::max(hi.x, h.x), std::max(hi.y, h.y)};
    }
    next.clear();
    std::vector<Vec2> rest, inside, outside;
    for (int k = 0; k < pieces.count(); ++k) {
        const Vec2* c = pieces.corners.data() + pieces.starts[k];
        const int n = pieces.starts[k + 1] - pieces.starts[k];
        bool apart = true;  // bounding boxes disjoint: nothing to cut
        for (int i = 0; i < n && apart; ++i)
            apart = !(c[i].x >= lo.x && c[i].x <= hi.x && c[i].y >= lo.y && c[i].y <= hi.y);
        if (apart) {
            Vec2 plo = c[0], phi = c[0];
            for (int i = 0; i < n; ++i) {
                plo = {std::min(plo.x, c[i].x), std::min(plo.y, c[i].y)};
                phi = {std::max(phi.x, c[i].x), std::max(phi.y, c[i].y)};
            }
            apart = plo.x > hi.x || phi.x < lo.x || plo.y > hi.y || phi.y < lo.y;
        }
        if (apart) {
            next.add(c, n);
            continue;
        }
        rest.assign(c, c + n);
        for (size_t e = 0; e < hole.size() && rest.size() >= 3; ++e) {
            const Vec2 p = hole[e], q = hole[(e + 1) % hole.size()];
            // Inside a counter-clockwise polygon is to the left of each edge.
            split(rest.data(), static_cast<int>(rest.size()), left_of(p, q), inside, outside);
            if (outside.size() >= 3 && std::abs(signed_area(outside)) > 1e-12f)
                next.add(outside.data(), static_cast<int>(outside.size()));
            rest.swap(inside);
        }
    }
    std::swap(pieces, next);
}

/// The corners' bounding box of polygon k of `polys`: {min a, min b, max a, max b}.
std::array<float, 4> bounding_box(const Pieces& polys, int k) {
    std::array<float, 4> box{k_infinity, k_infinity, -k_infinity, -k_infinity};
    for (int i = polys.starts[k]; i < polys.starts[k + 1]; ++i) {
        const Vec2 c = polys.corners[i];
        box = {std::min(box[0], c.x), std::min(box[1], c.y), std::max(box[2], c.x),
               std::max(box[3], c.y)};
    }
    return box;
}

/// The interval [t0, t1] of the segment a + t (b − a), t in [0, 1], that lies in convex
/// counter-clockwise polygon `c` (n corners), Cyrus & Beck 1978; empty when t0 >= t1. A segment
/// along an edge of c is inside where the edge runs the other way (the segment is a shared edge,
/// between two polygons of the union: not on its boundary), and inside where it runs the same
/// way only when `first` (two polygons with a boundary in common: the first one keeps it).
std::pair<float, float> inside_interval(Vec2 a, Vec2 b, const Vec2* c, int n, bool first) {
    constexpr float k_collinear = 1e-6f;  // light coordinates: the light is 1 wide
    float t0 = 0.0f, t1 = 1.0f;
    for (int e = 0; e < n && t0 < t1; ++e) {
        const Vec2 p = c[e], q = c[(e + 1) % n];
        const Line2 line = left_of(p, q);
        const float length = std::hypot(line.a, line.b);
        if (!(length > 0.0f)) continue;
        const float da = line.at(a) / length, db = line.at(b) / length;
        if (std::abs(da) <= k_collinear && std::abs(db) <= k_collinear) {
            const bool same_way = (b.x - a.x) * (q.x - p.x) + (b.y - a.y) * (q.y - p.y) > 0.0f;
            if (same_way && !first) return {1.0f, 0.0f};
            continue;
        }
        if (da >= 0.0f && db >= 0.0f) continue;
        if (da < 0.0f && db < 0.0f) return {1.0f, 0.0f};
        const float t = da / (da - db);
        if (da < 0.0f)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
    }
    return {t0, t1};
}

/// Calls emit(a, b) for every directed segment of the boundary of the union of the convex
/// counter-clockwise polygons `polys` (light coordinates): the parts of their edges inside no
/// other polygon, so counter-clockwise around the union and clockwise around its holes. A
/// uniform grid over the polygons' boxes finds the polygons an edge may enter (O(n) edges, each
/// against its neighbours, instead of every pair).
template <class Emit>
void union_boundary(const Pieces& polys, Emit&& emit) {
    const int count = polys.count();
    std::vector<std::array<float, 4>> boxes(static_cast<size_t>(count));
    std::array<float, 4> all{k_infinity, k_infinity, -k_infinity, -k_infinity};
    for (int k = 0; k < count; ++k) {
        boxes[k] = bounding_box(polys, k);
        all = {std::min(all[0], boxes[k][0]), std::min(all[1], boxes[k][1]),
               std::max(all[2], boxes[k][2]), std::max(all[3], boxes[k][3])};
    }
    const int g = std::clamp(static_cast<int>(std::sqrt(static_cast<float>(count))), 1, 64);
    const float sx = g / std::max(all[2] - all[0], 1e-12f),
                sy = g / std::max(all[3] - all[1], 1e-12f);
    const auto cell = [&](float v, float lo, float scale) {
        return std::clamp(static_cast<int>((v - lo) * scale), 0, g - 1);
    };
    std::vector<std::vector<int>> grid(static_cast<size_t>(g * g));
    for (int k = 0; k < count; ++k)
        for (int y = cell(boxes[k][1], all[1], sy); y <= cell(boxes[k][3], all[1], sy); ++y)
            for (int x = cell(boxes[k][0], all[0], sx); x <= cell(boxes[k][2], all[0], sx); ++x)
                grid[static_cast<size_t>(y * g + x)].push_back(k);
    std::vector<int> seen_by(static_cast<size_t>(count), -1);
    std::vector<std::pair<float, float>> covered;
    int edge_id = 0;
    for (int i = 0; i < count; ++i) {
        const Vec2* c = polys.corners.data() + polys.starts[i];
        const int n = polys.starts[i + 1] - polys.starts[i];
        for (int e = 0; e < n; ++e, ++edge_id) {
            const Vec2 a = c[e], b = c[(e + 1) % n];
            const float lo_x = std::min(a.x, b.x), hi_x = std::max(a.x, b.x);
            const float lo_y = std::min(a.y, b.y), hi_y = std::max(a.y, b.y);
            covered.clear();
            for (int y = cell(lo_y, all[1], sy); y <= cell(hi_y, all[1], sy); ++y)
                for (int x = cell(lo_x, all[0], sx); x <= cell(hi_x, all[0], sx); ++x)
                    for (const int j : grid[static_cast<size_t>(y * g + x)]) {
                        if (j == i || seen_by[j] == edge_id) continue;
                        seen_by[j] = edge_id;
                        const std::array<float, 4>& box = boxes[j];
                        if (box[0] > hi_x || box[2] < lo_x || box[1] > hi_y || box[3] < lo_y)
                            continue;
                        const auto t =
                            inside_interval(a, b, polys.corners.data() + polys.starts[j],
                                            polys.starts[j + 1] - polys.starts[j], j < i);
                        if (t.first < t.second) covered.push_back(t);
                    }
            // The gaps between the covered intervals are on the union's boundary.
            std::sort(covered.begin(), covered.end());
            float from = 0.0f;
            const auto at = [&](float t) {
                return Vec2{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
            };
            for (const auto& [t0, t1] : covered) {
                if (t0 > from) emit(at(from), at(t0));
                from = std::max(from, t1);
            }
            if (from < 1.0f) emit(at(from), b);
        }
    }
}

/// Sides of the polygon that stands for a sphere's outline.
constexpr int k_outline_sides = 32;

/// The outline of `sphere` seen from `p` as a polygon, if the sphere may meet the region of
/// `bounds` and p is outside it: the circle where the cone of sight from p touches the sphere
/// (centre c + a r² / D, radius r √(1 − r² / D²), a the unit vector toward p, D the distance),
/// as a regular polygon of the circle's area.
bool sphere_outline(const Sphere& sphere, Vec3 p, const std::array<Vec4, 7>& bounds,
                    std::vector<Vec3>& out) {
    for (const Vec4& b : bounds)
        if (dot(b.xyz(), sphere.center) - b.w < -sphere.radius * length(b.xyz())) return false;
    const Vec3 to_p = p - sphere.center;
    const float d2 = dot(to_p, to_p), r2 = sphere.radius * sphere.radius;
    if (!(d2 > r2 * k_own_sphere)) return false;  // p on the sphere: its horizon decides
    const float d = std::sqrt(d2);
    const Vec3 a = to_p / d;
    const Vec3 centre = sphere.center + a * (r2 / d);
    constexpr float k_step = 2.0f * std::numbers::pi_v<float> / k_outline_sides;
    const float radius = sphere.radius * std::sqrt(1.0f - r2 / d2) *
                         std::sqrt(k_step / std::sin(k_step));  // the polygon's area = the disc's
    const OrthonormalBasis frame(a);
    out.clear();
    for (int i = 0; i < k_outline_sides; ++i) {
        const float angle = k_step * static_cast<float>(i);
        out.push_back(centre + radius * (std::cos(angle) * frame.t + std::sin(angle) * frame.b));
    }
    return true;
}

}  // namespace

namespace {

/// Whether (a, b) lies in one of the convex counter-clockwise polygons `corners`, `starts`.
bool in_any(const std::vector<Vec2>& corners, const std::vector<int>& starts, Vec2 ab) {
    for (size_t k = 0; k + 1 < starts.size(); ++k) {
        bool in = true;
        const int first = starts[k], n = starts[k + 1] - first;
        for (int i = 0; i < n && in; ++i) {
            const Vec2 p = corners[first + i], q = corners[first + (i + 1) % n];
            in = (q.x - p.x) * (ab.y - p.y) - (q.y - p.y) * (ab.x - p.x) >= 0.0f;
        }
        if (in) return true;
    }
    return false;
}

/// Lambert's term of one directed edge a → b (world space) seen from p with unit normal n:
/// γ · n·(va × vb) / |va × vb|; half the sum over a closed contour, signed by its orientation,
/// is ∫ cos θ dω over what it encloses.
double lambert_edge(Vec3 p, Vec3 n, Vec3 a_world, Vec3 b_world) {
    const Vec3 a = a_world - p, b = b_world - p;
    const double ax = a.x, ay = a.y, az = a.z, bx = b.x, by = b.y, bz = b.z;
    const double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
    const double cross_len = std::sqrt(cx * cx + cy * cy + cz * cz);
    if (!(cross_len > 0.0)) return 0.0;
    const double gamma = std::atan2(cross_len, ax * bx + ay * by + az * bz);
    return gamma * (n.x * cx + n.y * cy + n.z * cz) / cross_len;
}

}  // namespace

bool VisibleLight::sees(Vec2 ab) const {
    return in_any(corners, starts, ab) && !in_any(hole_corners, hole_starts, ab);
}

double polygon_cosine_solid_angle(Vec3 p, Vec3 n, const Vec3* corners, int count) {
    double sum = 0.0;
    for (int i = 0; i < count; ++i) sum += lambert_edge(p, n, corners[i], corners[(i + 1) % count]);
    return 0.5 * std::abs(sum);
}

namespace {

/// What point p (unit normal n) sees of `light`, the single convex piece of the light above
/// its horizon and its planes, past the many convex shadows `holes`: each hole clipped to the
/// light, then ∫ cos θ dω over their union by Lambert's formula on the union's boundary
/// (union_boundary), taken from the light's. Exact for any number of occluders, and with no
/// cut pieces to multiply: the cost grows with the holes' edges, not with their overlaps.
VisibleLight union_shadow(const LightFrame& f, Vec3 p, Vec3 n, Pieces light, const Pieces& holes) {
    VisibleLight out;
    if (light.count() != 1) return out;  // nothing of the light above the horizon and planes
    const Vec2* region = light.corners.data();
    const int sides = light.starts[1];
    Pieces clipped;
    std::vector<Vec2> poly, inside, outside;
    for (int k = 0; k < holes.count(); ++k) {
        poly.assign(holes.corners.begin() + holes.starts[k],
                    holes.corners.begin() + holes.starts[k + 1]);
        for (int e = 0; e < sides && poly.size() >= 3; ++e) {
            split(poly.data(), static_cast<int>(poly.size()),
                  left_of(region[e], region[(e + 1) % sides]), inside, outside);
            poly.swap(inside);
        }
        if (poly.size() >= 3 && std::abs(signed_area(poly)) > 1e-12f)
            clipped.add(poly.data(), static_cast<int>(poly.size()));
    }
    // Lambert's sum is signed by the contour's orientation: the light's own (counter-clockwise
    // in (a, b)) tells which sign encloses.
    double open = 0.0;
    for (int i = 0; i < sides; ++i)
        open += lambert_edge(p, n, f.world(region[i]), f.world(region[(i + 1) % sides]));
    double hidden = 0.0;
    union_boundary(clipped,
                   [&](Vec2 a, Vec2 b) { hidden += lambert_edge(p, n, f.world(a), f.world(b)); });
    const double sign = open < 0.0 ? -1.0 : 1.0;
    out.cosine_solid_angle = static_cast<float>(
        std::max(0.0, 0.5 * sign * open - std::clamp(0.5 * sign * hidden, 0.0, 0.5 * sign * open)));
    out.corners = std::move(light.corners);
    out.starts = std::move(light.starts);
    out.hole_corners = std::move(clipped.corners);
    out.hole_starts = std::move(clipped.starts);
    return out;
}

}  // namespace

VisibleLight visible_light(const AreaLight& light, Vec3 p, Vec3 n, Vec3 ng,
                           const OccluderSet* occluders) {
    VisibleLight out;
    const Vec3 normal = light.area_normal();
    const float area2 = dot(normal, normal);
    if (!(area2 > 0.0f)) return out;
    LightFrame f{light.corner,
                 light.edge1,
                 light.edge2,
                 normal / std::sqrt(area2),
                 cross(light.edge2, normal) / area2,
                 cross(normal, light.edge1) / area2};
    f.height = f.above(p);
    if (f.height < 0.0f) {
        if (!light.two_sided) return out;
        f.unit_normal = -f.unit_normal;
        f.height = -f.height;
    }
    if (!(f.height > 0.0f)) return out;

    // The light square, cut to the point's horizon: dot(n, y − p) >= 0.
    Pieces pieces, next;
    {
        const Vec2 square[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        std::vector<Vec2> above, below;
        const Line2 horizon{dot(n, f.e1), dot(n, f.e2), dot(n, f.corner - p)};
        split(square, 4, horizon, above, below);
        if (above.size() < 3) return out;
        pieces.add(above.data(), static_cast<int>(above.size()));
    }

    if (occluders) {
        // Planes: the part of the light on the far side of a plane from p is hidden.
        for (const Plane& plane : occluders->planes()) {
            const float side = dot(p - plane.point, plane.normal);
            if (!(std::abs(side) > 1e-4f * (1.0f + length(p - plane.point)))) continue;
            const Vec3 m = side > 0.0f ? plane.normal : -plane.normal;
            const Line2 keep{dot(m, f.e1), dot(m, f.e2), dot(m, f.corner - plane.point)};
            next.clear();
            std::vector<Vec2> inside, outside;
            for (int k = 0; k < pieces.count(); ++k) {
                split(pieces.corners.data() + pieces.starts[k],
                      pieces.starts[k + 1] - pieces.starts[k], keep, inside, outside);
                if (inside.size() >= 3) next.add(inside.data(), static_cast<int>(inside.size()));
            }
            std::swap(pieces, next);
        }
        // Triangles in the pyramid from p to the light, between p's plane and the light's.
        const float scale = 1.0f + std::max(std::abs(p.x), std::max(std::abs(p.y), std::abs(p.z)));
        const float eps = 1e-5f * scale;
        std::array<Vec4, 7> bounds;
        const Vec3 corners[4] = {f.world({0, 0}), f.world({1, 0}), f.world({1, 1}),
                                 f.world({0, 1})};
        const Vec3 centre = light.centre();
        for (int i = 0; i < 4; ++i) {
            Vec3 m = cross(corners[i] - p, corners[(i + 1) % 4] - p);
            if (dot(m, centre - p) < 0.0f) m = -m;
            bounds[i] = Vec4(m.x, m.y, m.z, dot(m, p));
        }
        const Vec3 u = f.unit_normal;
        bounds[4] = Vec4(u.x, u.y, u.z, dot(u, f.corner) + eps);  // the light's side
        bounds[5] = Vec4(-u.x, -u.y, -u.z, -dot(u, p) + eps);     // nearer than p
        bounds[6] = Vec4(ng.x, ng.y, ng.z, dot(ng, p) + eps);     // above p's surface
        // Every occluder's shadow on the light, projected first, then cut out largest first:
        // the big ones leave fewer pieces for the small ones to cut.
        Pieces holes;
        std::vector<Vec3> poly, scratch;
        std::vector<Vec2> hole;
        std::vector<std::pair<float, int>> order;
        const auto project = [&]() {
            for (int k = 4; k < 7 && poly.size() >= 3; ++k)
                clip3(poly, scratch, bounds[k].xyz(), bounds[k].w);
            if (poly.size() < 3) return;
            // Central projection from p onto the light's plane.
            hole.clear();
            for (const Vec3 q : poly) {
                const float toward = f.height - f.above(q);  // > 0: q is nearer the light
                hole.push_back(f.coords(p + (q - p) * (f.height / toward)));
            }
            const float area = signed_area(hole);
            if (!(std::abs(area) > 1e-10f)) return;
            if (area < 0.0f) std::reverse(hole.begin(), hole.end());
            order.emplace_back(-std::abs(area), holes.count());
            holes.add(hole.data(), static_cast<int>(hole.size()));
        };
        occluders->for_each_triangle_in(bounds, [&](Vec3 a, Vec3 b, Vec3 c) {
            poly.assign({a, b, c});
            project();
        });
        occluders->for_each_sphere_in(bounds, [&](const Sphere& sphere) {
            if (sphere_outline(sphere, p, bounds, poly)) project();
        });
        if (order.size() > k_max_cut_occluders)
            return union_shadow(f, p, n, std::move(pieces), holes);
        std::sort(order.begin(), order.end());
        for (const auto& [area, k] : order) {
            if (pieces.count() == 0) break;
            hole.assign(holes.corners.begin() + holes.starts[k],
                        holes.corners.begin() + holes.starts[k + 1]);
            subtract(pieces, next, hole);
        }
    }

    out.corners = std::move(pieces.corners);
    out.starts = std::move(pieces.starts);
    double e = 0.0;
    std::vector<Vec3> world;
    for (size_t k = 0; k + 1 < out.starts.size(); ++k) {
        world.clear();
        for (int i = out.starts[k]; i < out.starts[k + 1]; ++i)
            world.push_back(f.world(out.corners[i]));
        e += polygon_cosine_solid_angle(p, n, world.data(), static_cast<int>(world.size()));
    }
    out.cosine_solid_angle = static_cast<float>(e);
    return out;
}

}  // namespace hikari
