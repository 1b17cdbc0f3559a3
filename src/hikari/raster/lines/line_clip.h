#pragma once
// Clipping a line segment in homogeneous clip space (Liang & Barsky 1984, in the homogeneous form
// of Blinn & Newell 1978), as raster/clip.h clips triangles: before the perspective divide, so
// that an edge reaching behind the eye is cut at the near plane, not dropped or wrapped through
// infinity.

#include <optional>

#include "hikari/core/vec.h"

namespace hikari {

/// The parameter interval of the clip-space segment a + t (b − a), t ∈ [0, 1].
struct ClipInterval {
    float t0 = 0;  ///< where the visible part starts
    float t1 = 1;  ///< where it ends
};

/// The part of segment (a, b) inside the near plane (z ≥ −w) and the view frustum's sides
/// widened by `margin` in NDC units (|x|, |y| ≤ (1 + margin) w), or nullopt when none is.
std::optional<ClipInterval> clip_segment(Vec4 a, Vec4 b, float margin = 0.0f);

}  // namespace hikari
