#pragma once
// Where two triangles pierce each other (Möller 1997, "A fast triangle-triangle intersection
// test"): each triangle crosses the other's plane along a segment of the planes' common line;
// the overlap of the two segments is the intersection line, which a hidden-line drawing shows as
// an edge.

#include "hikari/core/vec.h"

namespace hikari {

/// The segment (p, q) where triangle (a0, a1, a2) and triangle (b0, b1, b2) intersect, when
/// they cross along a segment of nonzero length; false when they are apart, touch at a point,
/// or are coplanar. World space.
bool triangle_intersection(const Vec3 a[3], const Vec3 b[3], Vec3& p, Vec3& q);

}  // namespace hikari
