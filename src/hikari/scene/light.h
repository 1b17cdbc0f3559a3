#pragma once
// Light sources of the lecture ("CG でよく使われる光源") as plain data: a closed set of kinds.
// What each delivers to a surface point is in shading/lights/ (one file per kind).

#include <variant>

#include "hikari/core/vec.h"

namespace hikari {

/// Light from one point; irradiance falls off as intensity / d² (or not at all, as POV-Ray's
/// default light without fade). Sampled by shading/lights/point_light.h.
struct PointLight {
    Vec3 position;
    Vec3 intensity;
    bool inverse_square = true;  ///< false: irradiance = intensity at any distance
};

/// Light from infinitely far away (the sun); no falloff. Sampled by
/// shading/lights/directional_light.h.
struct DirectionalLight {
    Vec3 direction;  ///< unit direction in which the light travels (L_in), world space
    Vec3 intensity;
};

/// Every light kind. Adding one: its struct here and in this list, its sampling routine in
/// shading/lights/ (included by shading/lights.h), its key in io/scene_json.cpp and
/// docs/scene-format.md.
using Light = std::variant<PointLight, DirectionalLight>;

}  // namespace hikari
