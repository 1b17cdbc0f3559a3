#pragma once
// Back-face culling (the lecture's Fig 4.3, 4.5): a polygon whose front side faces away from the
// eye cannot be seen on a closed object and is dropped before rasterization.

#include "hikari/core/vec.h"

namespace hikari {

/// The lecture's polygon normal N = (P2 − P1) × (P3 − P2): it points toward a viewer who sees
/// P1, P2, P3 run counter-clockwise (the front side, docs/scene-format.md "Winding").
constexpr Vec3 face_normal(Vec3 p1, Vec3 p2, Vec3 p3) { return cross(p2 - p1, p3 - p2); }

/// True when the eye sees the back of triangle (p1, p2, p3): D = V·N > 0 with V the view
/// vector from the eye to the triangle (P1 − eye) and N = face_normal. Edge-on triangles
/// (D = 0) are kept; they cover no pixel centre anyway. All points in world space.
constexpr bool is_back_face(Vec3 p1, Vec3 p2, Vec3 p3, Vec3 eye) {
    return dot(p1 - eye, face_normal(p1, p2, p3)) > 0.0f;
}

}  // namespace hikari
