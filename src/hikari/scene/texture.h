#pragma once
// Textures as plain data: the closed set of kinds a material can carry. How each is evaluated
// at a surface point is in shading/textures/ (one file per kind).

#include <variant>

#include "hikari/core/vec.h"

namespace hikari {

/// A solid checker (POV-Ray's `checker` pattern): colour_a where
/// floor((x + offset.x) / size) + floor((y + offset.y) / size) + floor((z + offset.z) / size) is
/// even, colour_b where it is odd. Linear RGB; evaluated by shading/textures/checker_texture.h.
struct CheckerTexture {
    float size = 1.0f;  ///< edge of one cube, world units (> 0)
    Vec3 color_a{1.0f};
    Vec3 color_b{0.0f};
    Vec3 offset{0.0f};  ///< added to the point first (moves the pattern by -offset)
};

/// Every texture kind. Adding one: its struct here and in this list, its evaluation in
/// shading/textures/, its key in io/scene_json.cpp and docs/scene-format.md.
using Texture = std::variant<CheckerTexture>;

}  // namespace hikari
