#pragma once
// Shooting single rays through a triangle BVH: nearest hit (camera, reflection, refraction rays)
// and any hit (shadow rays).

#include <cstdint>

#include "hikari/bvh/bvh.h"
#include "hikari/core/ray.h"

namespace hikari {

/// The nearest triangle along a ray.
struct TriangleHit {
    float t = 0;            ///< distance along the ray, in units of |ray.direction|
    float u = 0;            ///< barycentric weight of the triangle's second vertex
    float v = 0;            ///< barycentric weight of the third vertex (the first gets 1 - u - v)
    uint32_t triangle = 0;  ///< index of the triangle in the input given to build_bvh
};

/// Finds the nearest triangle hit by `ray` with t inside the open interval `valid`.
/// Returns false (and leaves `hit` alone) when there is none. Of several triangles at exactly
/// the same distance, one is reported. The direction need not be unit length; a zero or
/// non-finite direction hits nothing.
bool intersect_closest(const Bvh& bvh, const Ray& ray, Interval valid, TriangleHit& hit);

/// True when `ray` hits any triangle with t inside the open interval `valid` (shadow rays:
/// stops at the first hit found, not the nearest).
bool intersect_any(const Bvh& bvh, const Ray& ray, Interval valid);

}  // namespace hikari
