#pragma once
// Ray–sphere and ray–plane intersection (the lecture's "レイと物体との交差判定").

#include <cmath>

#include "hikari/core/ray.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// Nearest t of `ray` (unit direction) with the sphere inside `range`, or NaN when there is none.
/// The lecture's ‖P_E + tÊ − S‖ = r becomes A t² + B t + C = 0 with A = 1; we solve it in the
/// numerically stable form of Haines et al., "Precision Improvements for Ray/Sphere Intersection"
/// (Ray Tracing Gems, ch. 7): the discriminant from the perpendicular distance to the centre
/// (no catastrophic cancellation for far spheres) and the second root as C/q (none for near
/// roots of opposite sign).
HIKARI_HD inline float intersect_sphere(const Ray& ray, Vec3 center, float radius, Interval range) {
    const Vec3 f = ray.origin - center;
    const float b = -dot(f, ray.direction);  // −B/2
    const Vec3 perpendicular = f + b * ray.direction;
    const float r2 = radius * radius;
    const float discriminant = r2 - dot(perpendicular, perpendicular);  // (B² − 4AC) / 4
    if (discriminant < 0.0f) return NAN;
    const float c = dot(f, f) - r2;
    // Origin outside (C > 0) and centre behind (b ≤ 0): both roots ≤ 0, so no hit in a range
    // that starts at 0 or later. Skips the square root for most rays that miss.
    if (c > 0.0f && b <= 0.0f && range.min >= 0.0f) return NAN;
    const float q = b + std::copysign(std::sqrt(discriminant), b);
    float t0 = c / q;  // q has the sign of b, so these are the two roots with no cancellation
    float t1 = q;
    if (q == 0.0f) t0 = t1 = 0.0f;  // ray origin on the sphere, tangent: both roots at 0
    if (t0 > t1) std::swap(t0, t1);
    if (range.surrounds(t0)) return t0;
    if (range.surrounds(t1)) return t1;
    return NAN;
}

/// t of `ray` with the infinite plane through `point` with normal `normal`, or NaN when the ray
/// is parallel to it or the hit is outside `range`.
HIKARI_HD inline float intersect_plane(const Ray& ray, Vec3 point, Vec3 normal, Interval range) {
    const float denom = dot(normal, ray.direction);
    if (denom == 0.0f) return NAN;
    const float t = dot(point - ray.origin, normal) / denom;
    return range.surrounds(t) ? t : NAN;
}

}  // namespace hikari
