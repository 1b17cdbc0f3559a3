#pragma once
// Back-face culling (the lecture's Fig 4.3, 4.5): a polygon whose front side faces away from the
// eye cannot be seen on a closed object and is dropped before rasterization.

#include "hikari/core/vec.h"

namespace hikari {

/// The lecture's polygon normal N = (P2 − P1) × (P3 − P2): it points toward a viewer who sees
/// P1, P2, P3 run counter-clockwise (the front side, docs/scene-format.md "Winding").
constexpr Vec3 face_normal(Vec3 p1, Vec3 p2, Vec3 p3) { return cross(p2 - p1, p3 - p2); }

/// True when a viewer looking along `view` (the view vector V toward the triangle) sees the
/// back of triangle (p1, p2, p3): D = V·N > 0 with N = face_normal. Edge-on triangles (D = 0)
/// are kept; they cover no pixel centre anyway. All in world space.
constexpr bool is_back_face_along(Vec3 p1, Vec3 p2, Vec3 p3, Vec3 view) {
    return dot(view, face_normal(p1, p2, p3)) > 0.0f;
}

/// The same seen from the point `eye` (a pinhole): V = P1 − eye.
constexpr bool is_back_face(Vec3 p1, Vec3 p2, Vec3 p3, Vec3 eye) {
    return is_back_face_along(p1, p2, p3, p1 - eye);
}

}  // namespace hikari
