#pragma once
// The line methods' own settings (wireframe, hiddenline).

#include <optional>

#include "hikari/core/vec.h"

namespace hikari {

/// Settings of the line methods (`--line-width`, `--line-color`, `--cull`).
struct LineSettings {
    float width = 1.0f;            ///< stroke width in pixels
    std::optional<Vec3> color;     ///< linear RGB of every line; unset: each face's material kd
    bool cull_back_faces = false;  ///< drop faces seen from behind, and the edges of only those
    /// Draw every triangle edge, the diagonals that split the model's polygons included (what
    /// the raster methods fill and interpolate over: --wireframe-overlay).
    bool triangle_edges = false;
};

}  // namespace hikari
