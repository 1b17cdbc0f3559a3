#pragma once
// What a ray query against the BVH answers: which triangle is nearest along the ray, and where on
// it. Every traversal (single rays, packets, tiles; wide_bvh_traversal.h, wide_bvh_packet.h)
// reports it, and the scene intersector turns it into a surface hit.

#include <cstdint>

namespace hikari {

/// The nearest triangle along a ray.
struct TriangleHit {
    float t = 0;            ///< distance along the ray, in units of |ray.direction|
    float u = 0;            ///< barycentric weight of the triangle's second vertex
    float v = 0;            ///< barycentric weight of the third vertex (the first gets 1 - u - v)
    uint32_t triangle = 0;  ///< index of the triangle in the input given to build_wide_bvh
};

}  // namespace hikari
