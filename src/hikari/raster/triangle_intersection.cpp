#include "hikari/raster/triangle_intersection.h"

#include <algorithm>

namespace hikari {

namespace {

/// The part of triangle `t` on the plane with signed vertex distances `d`, as the extent
/// [lo, hi] along `dir` and the two points there; false when it is a point or nothing.
bool plane_crossing(const Vec3 t[3], const float d[3], Vec3 dir, float& lo, float& hi, Vec3& p_lo,
                    Vec3& p_hi) {
    Vec3 points[3];
    int n = 0;
    for (int k = 0; k < 3 && n < 3; ++k) {
        const int j = (k + 1) % 3;
        if (d[k] == 0.0f) points[n++] = t[k];
        if ((d[k] < 0.0f && d[j] > 0.0f) || (d[k] > 0.0f && d[j] < 0.0f))
            points[n++] = t[k] + (t[j] - t[k]) * (d[k] / (d[k] - d[j]));
    }
    if (n < 2) return false;
    lo = hi = dot(points[0], dir);
    p_lo = p_hi = points[0];
    for (int k = 1; k < n; ++k) {
        const float s = dot(points[k], dir);
        if (s < lo) lo = s, p_lo = points[k];
        if (s > hi) hi = s, p_hi = points[k];
    }
    return hi > lo;
}

/// Signed distances (scaled by |n|) of `t`'s corners to the plane of `u`; false when `t` lies
/// strictly on one side of it, or in it.
bool straddles(const Vec3 t[3], const Vec3 u[3], Vec3& n, float d[3]) {
    n = cross(u[1] - u[0], u[2] - u[0]);
    for (int k = 0; k < 3; ++k) d[k] = dot(n, t[k] - u[0]);
    const bool all_above = d[0] > 0.0f && d[1] > 0.0f && d[2] > 0.0f;
    const bool all_below = d[0] < 0.0f && d[1] < 0.0f && d[2] < 0.0f;
    const bool in_plane = d[0] == 0.0f && d[1] == 0.0f && d[2] == 0.0f;
    return !all_above && !all_below && !in_plane;
}

}  // namespace

bool triangle_intersection(const Vec3 a[3], const Vec3 b[3], Vec3& p, Vec3& q) {
    Vec3 nb, na;
    float da[3], db[3];
    if (!straddles(a, b, nb, da) || !straddles(b, a, na, db)) return false;
    const Vec3 dir = cross(na, nb);
    if (!(dot(dir, dir) > 0.0f)) return false;
    // Both crossings lie on the planes' common line; their overlap is the intersection.
    float a_lo, a_hi, b_lo, b_hi;
    Vec3 a_plo, a_phi, b_plo, b_phi;
    if (!plane_crossing(a, da, dir, a_lo, a_hi, a_plo, a_phi) ||
        !plane_crossing(b, db, dir, b_lo, b_hi, b_plo, b_phi))
        return false;
    if (!(std::min(a_hi, b_hi) > std::max(a_lo, b_lo))) return false;
    p = a_lo >= b_lo ? a_plo : b_plo;
    q = a_hi <= b_hi ? a_phi : b_phi;
    return true;
}

}  // namespace hikari
