#pragma once
// Shooting single rays through the wide BVH: nearest hit (camera, reflection, refraction rays)
// and any hit (shadow rays). Each query runs the kernel of the best SIMD level the CPU has;
// every level returns bit-identical answers, equal to testing every triangle with
// intersect_triangle (watertight, Woop et al. 2013).

#include "hikari/bvh/sphere_bvh.h"
#include "hikari/bvh/triangle_hit.h"
#include "hikari/bvh/wide_bvh.h"
#include "hikari/core/ray.h"
#include "hikari/core/simd_level.h"

namespace hikari {

/// Finds the nearest triangle hit by `ray` with t inside the open interval `valid`, using the
/// CPU's best SIMD level. Returns false (and leaves `hit` alone) when there is none. Of several
/// triangles at exactly the same distance, one is reported (the same one at every level).
bool intersect_closest(const WideBvh& bvh, const Ray& ray, Interval valid, TriangleHit& hit);

/// True when `ray` hits any triangle with t inside the open interval `valid`.
bool intersect_any(const WideBvh& bvh, const Ray& ray, Interval valid);

/// intersect_closest with an explicit SIMD level (tests compare the levels; `level` must be
/// supported by this CPU, see simd_level_supported).
bool intersect_closest(const WideBvh& bvh, const Ray& ray, Interval valid, TriangleHit& hit,
                       SimdLevel level);

/// intersect_any with an explicit SIMD level.
bool intersect_any(const WideBvh& bvh, const Ray& ray, Interval valid, SimdLevel level);

/// Finds the nearest sphere of `bvh` hit by `ray` with t inside the open interval `valid`: the
/// t intersect_sphere gives, and of spheres at exactly that t the one of lowest index, so the
/// answer is that of testing every sphere in index order. Returns false (and leaves `hit` alone)
/// when there is none.
bool intersect_closest(const SphereBvh& bvh, const Ray& ray, Interval valid, SphereHit& hit);

/// True when `ray` hits any sphere of `bvh` with t inside the open interval `valid`.
bool intersect_any(const SphereBvh& bvh, const Ray& ray, Interval valid);

/// The sphere queries with an explicit SIMD level (for the boxes; the sphere test is the same).
bool intersect_closest(const SphereBvh& bvh, const Ray& ray, Interval valid, SphereHit& hit,
                       SimdLevel level);
bool intersect_any(const SphereBvh& bvh, const Ray& ray, Interval valid, SimdLevel level);

}  // namespace hikari
