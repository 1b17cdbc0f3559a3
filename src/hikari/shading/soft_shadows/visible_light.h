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
/// (a, b) in [0, 1]², the point corner + a·edge1 + b·edge2.
struct VisibleLight {
    std::vector<Vec2> corners;  ///< every piece's corners, counter-clockwise, one after another
    std::vector<int> starts;    ///< piece k's corners are [starts[k], starts[k + 1])
    /// ∫ cos θ dω over the visible pieces (θ from the normal): the irradiance divided by L.
    float cosine_solid_angle = 0;
    /// False when more than k_max_analytic_occluders occluders lie between the point and the
    /// light: the pieces were not cut (they hold the unoccluded light) and the caller samples
    /// the shadow instead (a dense mesh would cut the light into too many pieces).
    bool exact = true;

    size_t piece_count() const { return starts.empty() ? 0 : starts.size() - 1; }
    /// Whether light point (a, b) is among the visible pieces.
    bool sees(Vec2 ab) const;
};

/// The most occluder polygons one point's light is cut by in closed form.
inline constexpr size_t k_max_analytic_occluders = 96;

/// What of `light` the point `p` with unit shading normal `n` sees above its horizon, past the
/// triangles and planes of `occluders` (none when null). `ng` is the unit geometric normal on
/// the side light may arrive from: occluders behind the surface's own plane through p are
/// ignored (they cannot block light that reaches the surface, and the surface itself is there).
VisibleLight visible_light(const AreaLight& light, Vec3 p, Vec3 n, Vec3 ng,
                           const OccluderSet* occluders);

/// The share of `light`'s diffuse light at `p` (unit normal `n`, geometric normal `ng` on the
/// light's side) that `occluders` let through, from `samples` stratified points of the light,
/// each tested with a segment toward it: what replaces visible_light when it is not exact.
float sampled_light_fraction(const AreaLight& light, Vec3 p, Vec3 n, Vec3 ng,
                             const OccluderSet& occluders, int samples);

/// ∫ cos θ dω over the polygon `corners` (world space) seen from `p` with unit normal `n`:
/// Lambert's contour formula, for a polygon wholly above the horizon of p.
double polygon_cosine_solid_angle(Vec3 p, Vec3 n, const Vec3* corners, int count);

}  // namespace hikari
