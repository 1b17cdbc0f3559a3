#pragma once
// The analytic soft shadow of a polygonal area light (Nishita & Nakamae 1983, "Half-tone
// representation of 3-D objects illuminated by area sources or polyhedron sources"): from one
// shaded point, the occluders are projected onto the light's plane, the light polygon is clipped
// against them, and the diffuse light of what stays visible is integrated in closed form by
// Lambert's contour formula (Lambert 1760; the "polygonal light" irradiance of Arvo 1995):
//   E = L/2 · Σ_edges γ_i · n · (v_i × v_{i+1}) / |v_i × v_{i+1}|,
// v_i the vectors from the point to the polygon's corners, γ_i the angle between v_i and
// v_{i+1}, n the surface normal.

#include <vector>

#include "hikari/core/vec.h"
#include "hikari/scene/light.h"
#include "hikari/shading/soft_shadows/occluders.h"

namespace hikari {

/// The part of an area light a point sees: convex pieces in the light's own coordinates
/// (a, b) in [0, 1]², the point corner + a·edge1 + b·edge2, less the convex holes (when many
/// occluders are not cut out of the pieces one by one, but integrated as a union).
struct VisibleLight {
    std::vector<Vec2> corners;  ///< every piece's corners, counter-clockwise, one after another
    std::vector<int> starts;    ///< piece k's corners are [starts[k], starts[k + 1])
    /// The occluders' shadows on the light, counter-clockwise, as `corners` and `starts`; empty
    /// when they were cut out of the pieces.
    std::vector<Vec2> hole_corners;
    std::vector<int> hole_starts;
    /// ∫ cos θ dω over the visible part (θ from the normal): the irradiance divided by L.
    float cosine_solid_angle = 0;

    size_t piece_count() const { return starts.empty() ? 0 : starts.size() - 1; }
    /// Whether light point (a, b) is among the visible pieces and in none of the holes.
    bool sees(Vec2 ab) const;
};

/// Up to this many occluder polygons, the light is cut by each in turn into convex pieces;
/// beyond (a dense mesh, whose cuts would shatter it), the shadow is the union of the
/// occluders' polygons, integrated over the union's boundary (visible_light.cpp). Both exact.
inline constexpr size_t k_max_cut_occluders = 96;

/// What of `light` the point `p` with unit shading normal `n` sees above its horizon, past the
/// triangles and planes of `occluders` (none when null). `ng` is the unit geometric normal on
/// the side light may arrive from: occluders behind the surface's own plane through p are
/// ignored (they cannot block light that reaches the surface, and the surface itself is there).
VisibleLight visible_light(const AreaLight& light, Vec3 p, Vec3 n, Vec3 ng,
                           const OccluderSet* occluders);

/// ∫ cos θ dω over the polygon `corners` (world space) seen from `p` with unit normal `n`:
/// Lambert's contour formula, for a polygon wholly above the horizon of p.
double polygon_cosine_solid_angle(Vec3 p, Vec3 n, const Vec3* corners, int count);

}  // namespace hikari
