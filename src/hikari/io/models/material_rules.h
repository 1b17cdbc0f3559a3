#pragma once
// The ranges a material's coefficients must lie in, one rule for every format that gives
// materials (scene JSON, MTL, glTF), so a value refused in one is refused in all.

#include <optional>
#include <string>
#include <string_view>

#include "hikari/scene/material.h"

namespace hikari {

/// A coefficient of Material, named as the scene JSON names it.
enum class MaterialField { ka, kd, ks, shininess, reflectivity, transparency, ior, emission };

/// The first coefficient of a material that is out of range, and why.
struct MaterialProblem {
    MaterialField field;
    std::string message;  ///< "transparency must be from 0 to 1, got -1"
};

/// The field's name in the scene JSON: "ka", "shininess", ...
std::string_view material_field_name(MaterialField field);

/// Checks every coefficient of `m`: colours (ka, kd, ks, emission) finite and >= 0, shininess
/// finite and >= 0, reflectivity and transparency (weights of the mirror and refracted rays)
/// from 0 to 1, ior finite and > 0. Returns the first problem, or nothing when all are in range.
std::optional<MaterialProblem> find_material_problem(const Material& m);

}  // namespace hikari
