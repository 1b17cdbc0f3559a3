#pragma once
// Splitting a polygon face into triangles: a fan where that is right (convex polygons), ear
// clipping where it is not (concave ones, whose fan would cover area outside the face, the
// lecture's Fig 4.9c).

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "hikari/core/vec.h"

namespace hikari {

/// One triangle of a polygon: three of its corners (positions in the polygon's corner list), in
/// the polygon's own orientation, and which of its edges lie on the polygon's outline.
struct PolygonTriangle {
    std::array<uint32_t, 3> corner;
    /// Bit k set where the edge from corner[k] to corner[(k + 1) % 3] is an edge of the polygon
    /// (not a diagonal the triangulation added); TriangleSet::edge_flags.
    uint8_t edge_flags = 0;
};

/// What triangulate_polygon() found the polygon to be.
enum class PolygonShape {
    Convex,            ///< fanned from its first corner
    Concave,           ///< ear-clipped
    SelfIntersecting,  ///< edges cross: ear-clipped as well as can be, some area may be wrong
    Degenerate,        ///< no area (all corners on a line, or non-finite): fanned
};

/// Appends the n - 2 triangles of the polygon with the given corners (n >= 3, in order, roughly
/// planar) to `out`. The polygon is projected onto the plane of its Newell normal (Newell 1972);
/// convex polygons are fanned from corner 0, others triangulated by ear clipping (Meisters 1975:
/// cut off a convex corner whose triangle holds no other corner, until three are left).
PolygonShape triangulate_polygon(std::span<const Vec3> corners, std::vector<PolygonTriangle>& out);

}  // namespace hikari
