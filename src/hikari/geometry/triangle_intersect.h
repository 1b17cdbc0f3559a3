#pragma once
// Ray–triangle intersection, watertight: Woop, Benthin & Wald 2013, "Watertight Ray/Triangle
// Intersection", JCGT 2(1). A ray through an edge or vertex shared by several triangles hits at
// least one of them, never none, so ray-cast id buffers have no cracks along mesh edges.

#include <cmath>
#include <optional>
#include <utility>

#include "hikari/core/ray.h"
#include "hikari/core/vec.h"

namespace hikari {

/// Where a ray meets a triangle p0 p1 p2: the hit point is ray.at(t) =
/// (1 - u - v) p0 + u p1 + v p2 (up to rounding).
struct TriangleIntersection {
    float t = 0;  ///< distance along the ray, in units of |ray.direction|
    float u = 0;  ///< barycentric weight of vertex p1
    float v = 0;  ///< barycentric weight of vertex p2
};

/// The per-ray constants of the watertight test (Woop et al. 2013, Sec 3): the ray is mapped to
/// the +z axis by a permutation of axes and a shear, and triangles are tested in that space.
/// Computing them once per ray takes one division per axis out of every triangle test.
struct WatertightRay {
    Vec3 origin;                 ///< the ray origin, unchanged
    float Vec3::*kx = &Vec3::x;  ///< the axis that becomes x after the permutation
    float Vec3::*ky = &Vec3::y;  ///< the axis that becomes y
    float Vec3::*kz = &Vec3::z;  ///< the axis along which |direction| is largest
    float sx = 0;                ///< shear of x per unit z: d[kx] / d[kz]
    float sy = 0;                ///< shear of y per unit z: d[ky] / d[kz]
    float sz = 0;                ///< scale of z: 1 / d[kz]

    WatertightRay() = default;
    /// Precomputes the permutation and shear for `ray`. The direction need not be unit length
    /// but must be finite and non-zero; otherwise every test misses.
    HIKARI_HD explicit WatertightRay(const Ray& ray) : origin(ray.origin) {
        const Vec3 d = ray.direction;
        const Vec3 a{std::abs(d.x), std::abs(d.y), std::abs(d.z)};
        // Sec 3: kz is the dominant axis, kx and ky follow it cyclically.
        if (a.x >= a.y && a.x >= a.z) {
            kx = &Vec3::y, ky = &Vec3::z, kz = &Vec3::x;
        } else if (a.y >= a.z) {
            kx = &Vec3::z, ky = &Vec3::x, kz = &Vec3::y;
        }
        // Swapping kx and ky when d[kz] < 0 keeps the winding, so det > 0 means front-facing.
        if (d.*kz < 0.0f) std::swap(kx, ky);
        sx = d.*kx / d.*kz;
        sy = d.*ky / d.*kz;
        sz = 1.0f / d.*kz;
    }
};

/// How far the scaled distance may be off by rounding, relative to the sum of its terms'
/// magnitudes: a hit whose |t_scaled| is within this band of 0 lies at the ray's origin within
/// the precision of the triangle's own coordinates (a triangle whose plane contains the origin,
/// edge-on to the ray, "hit" at t ≈ 1e-7), and is a miss. 32 ulps: a true hit is rejected only
/// nearer than about 2e-6 of the distance to the triangle's vertices, inside the band that
/// secondary rays already leave by offset_ray_origin.
inline constexpr float k_t_rounding = 32.0f * 0x1p-24f;

/// A triangle the ray's line passes through, before the division: Woop et al. 2013's scaled
/// barycentrics (e0, e1, e2 weigh p0, p1, p2), their sum det (never 0), and the hit distance
/// times det.
struct ScaledTriangleHit {
    float e0 = 0, e1 = 0, e2 = 0;
    float det = 0;
    float t_scaled = 0;
};

/// Steps 1-5 of the watertight test for triangle p0 p1 p2, both sides (no culling), up to the
/// division: nothing when the ray's line misses it; degenerate (zero-area) triangles and NaN
/// inputs never hit.
HIKARI_HD inline std::optional<ScaledTriangleHit> scaled_triangle_hit(const WatertightRay& ray,
                                                                      const Vec3& p0,
                                                                      const Vec3& p1,
                                                                      const Vec3& p2) {
    // Steps 1-2: vertices relative to the origin, sheared so the ray runs along +z.
    const Vec3& o = ray.origin;
    const float az = p0.*ray.kz - o.*ray.kz;
    const float bz = p1.*ray.kz - o.*ray.kz;
    const float cz = p2.*ray.kz - o.*ray.kz;
    const float ax = (p0.*ray.kx - o.*ray.kx) - ray.sx * az;
    const float ay = (p0.*ray.ky - o.*ray.ky) - ray.sy * az;
    const float bx = (p1.*ray.kx - o.*ray.kx) - ray.sx * bz;
    const float by = (p1.*ray.ky - o.*ray.ky) - ray.sy * bz;
    const float cx = (p2.*ray.kx - o.*ray.kx) - ray.sx * cz;
    const float cy = (p2.*ray.ky - o.*ray.ky) - ray.sy * cz;

    // Step 3: scaled barycentrics = 2D edge functions at the origin of the sheared space.
    float e0 = cx * by - cy * bx;  // weight of p0
    float e1 = ax * cy - ay * cx;  // weight of p1
    float e2 = bx * ay - by * ax;  // weight of p2

    // Sec 4: on an edge, float rounding could give the two neighbours the same sign; redo the
    // products exactly (a float product is exact in double) so the sign is the true one.
    if (e0 == 0.0f || e1 == 0.0f || e2 == 0.0f) {
        e0 = static_cast<float>(double(cx) * by - double(cy) * bx);
        e1 = static_cast<float>(double(ax) * cy - double(ay) * cx);
        e2 = static_cast<float>(double(bx) * ay - double(by) * ax);
    }

    // Step 4: inside when all edge functions share a sign (either sign: double-sided).
    if ((e0 < 0.0f || e1 < 0.0f || e2 < 0.0f) && (e0 > 0.0f || e1 > 0.0f || e2 > 0.0f)) {
        return std::nullopt;
    }
    const float det = e0 + e1 + e2;
    if (det == 0.0f) return std::nullopt;

    // Step 5: the hit distance times det, interpolated from the vertices' scaled z.
    const float z0 = e0 * (ray.sz * az), z1 = e1 * (ray.sz * bz), z2 = e2 * (ray.sz * cz);
    const float t_scaled = z0 + z1 + z2;
    // Within rounding of the origin (the ray's line in the triangle's plane, or the origin on
    // it): no hit (k_t_rounding).
    if (!(std::abs(t_scaled) > k_t_rounding * (std::abs(z0) + std::abs(z1) + std::abs(z2))))
        return std::nullopt;
    return ScaledTriangleHit{e0, e1, e2, det, t_scaled};
}

/// Intersects a ray (as its precomputed WatertightRay) with triangle p0 p1 p2, both sides
/// (no culling). Returns the hit when its distance lies inside the open interval `valid`;
/// degenerate (zero-area) triangles and NaN inputs never hit.
HIKARI_HD inline std::optional<TriangleIntersection> intersect_triangle(
    const WatertightRay& ray, const Vec3& p0, const Vec3& p1, const Vec3& p2, Interval valid) {
    const auto hit = scaled_triangle_hit(ray, p0, p1, p2);
    if (!hit) return std::nullopt;
    const float inv_det = 1.0f / hit->det;
    const float t = hit->t_scaled * inv_det;
    if (!valid.surrounds(t)) return std::nullopt;
    return TriangleIntersection{t, hit->e1 * inv_det, hit->e2 * inv_det};
}

/// Whether t_scaled / det lies inside the open interval `valid`, decided without the division
/// (the depth test of Woop et al. 2013's listing): t_scaled with det's sign against the bounds
/// times |det|. A shadow ray needs no distance, and most triangles its line meets lie outside
/// its interval. Up to rounding the same answer as dividing; at a bound the two may differ by
/// an ulp of t.
HIKARI_HD inline bool scaled_distance_inside(float t_scaled, float det, Interval valid) {
    const float abs_det = std::abs(det);
    const float t_signed = det < 0.0f ? -t_scaled : t_scaled;
    return valid.min * abs_det < t_signed && t_signed < valid.max * abs_det;
}

/// The any-hit form of intersect_triangle (shadow rays): whether the ray meets triangle p0 p1
/// p2 inside `valid`, with the distance compared before the division, not computed
/// (scaled_distance_inside).
HIKARI_HD inline bool triangle_occludes(const WatertightRay& ray, const Vec3& p0, const Vec3& p1,
                                        const Vec3& p2, Interval valid) {
    const auto hit = scaled_triangle_hit(ray, p0, p1, p2);
    return hit && scaled_distance_inside(hit->t_scaled, hit->det, valid);
}

/// Convenience form for a single test: precomputes the WatertightRay for `ray` first.
HIKARI_HD inline std::optional<TriangleIntersection> intersect_triangle(
    const Ray& ray, const Vec3& p0, const Vec3& p1, const Vec3& p2, Interval valid) {
    return intersect_triangle(WatertightRay(ray), p0, p1, p2, valid);
}

}  // namespace hikari
