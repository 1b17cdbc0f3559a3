#pragma once
// The spheres of a scene in a wide BVH of their own: the same 8-wide nodes as the triangles'
// tree (wide_bvh.h), built by the same binned-SAH builder over the spheres' boxes, and walked by
// the same traversal loop with a sphere test at the leaves (wide_bvh_traversal.h). A ray asks it
// after the triangle tree, with the nearest triangle hit as its limit, so a scene of a million
// spheres costs one more tree walk per ray instead of a million tests.

#include <cstdint>
#include <span>

#include "hikari/bvh/wide_bvh.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// A wide BVH over spheres. The spheres of a leaf over slots [first, first + count) lie at
/// sphere_data[4 first ...] as four rows of `count` floats: centre x, y, z and radius, so one
/// SIMD step rules out eight of them (the layout of WideBvh's triangle rows).
struct SphereBvh {
    WideBvh tree;                       ///< nodes; tree.triangle_ids[slot] is the sphere's index
    HugePageVector<float> sphere_data;  ///< 4 floats per slot, plus 8 of padding so 8-wide
                                        ///< loads at a leaf's end stay inside

    /// True when the tree holds no sphere.
    bool empty() const { return tree.empty(); }
    /// Number of spheres held.
    size_t sphere_count() const { return tree.triangle_ids.size(); }
    /// Bytes held by nodes, sphere data and ids.
    size_t memory_bytes() const { return tree.memory_bytes() + sphere_data.size() * sizeof(float); }
};

/// The nearest sphere along a ray.
struct SphereHit {
    float t = 0;          ///< distance along the ray, as intersect_sphere gives it
    uint32_t sphere = 0;  ///< index into the span given to build_sphere_bvh
};

/// Builds the tree over `spheres` (indices into the span), or over those that cast shadows only
/// when `casters_only`. Spheres with a non-finite centre or radius are left out (they could
/// never be hit).
SphereBvh build_sphere_bvh(std::span<const Sphere> spheres, bool casters_only = false);

}  // namespace hikari
