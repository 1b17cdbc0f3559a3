#pragma once
// Sutherland–Hodgman clipping in homogeneous clip space (Sutherland & Hodgman 1974), before the
// perspective divide, so that triangles crossing the near plane or reaching behind the eye are
// cut, not dropped or smeared through infinity.

#include <array>

#include "hikari/core/vec.h"

namespace hikari {

/// Half-width of the guard band in NDC units: x and y are clipped to |x|, |y| ≤ k_guard_band · w.
/// Only the near plane changes what is visible; the guard band keeps screen coordinates small
/// enough for exact fixed-point edge functions, and its cuts fall outside the viewport.
inline constexpr float k_guard_band = 2.0f;

/// Most vertices a triangle can have after clipping by the five planes.
inline constexpr int k_max_clip_vertices = 8;

/// A convex polygon in clip space, vertices in the order of the input triangle's winding.
struct ClipPolygon {
    std::array<Vec4, k_max_clip_vertices> v;
    int count = 0;
};

/// True when a clip-space point lies inside the near plane (z ≥ −w, which implies w > 0 for a
/// perspective projection) and the guard band.
bool inside_clip_volume(Vec4 p);

/// Clips the clip-space triangle (a, b, c) against the near plane z = −w and the guard band
/// planes x = ±g w, y = ±g w (g = k_guard_band). The result has 0 (fully outside) or 3 to 8
/// vertices. An edge shared by two triangles is cut at bit-identical points in both, since each
/// intersection is computed from the edge's inside end: clipped meshes stay watertight.
ClipPolygon clip_triangle(Vec4 a, Vec4 b, Vec4 c);

}  // namespace hikari
