#pragma once
// Surface reflectance for the lecture's shading model (Fig 4.29) and Whitted's secondary rays.

#include <optional>
#include <string>

#include "hikari/core/vec.h"
#include "hikari/scene/texture.h"

namespace hikari {

/// Coefficients of ambient + Lambert diffuse + Phong specular, plus the weights of the mirror
/// and refracted rays of Whitted ray tracing. Colours are linear RGB.
struct Material {
    std::string name;
    Vec3 ka{0.0f};           ///< ambient reflectance: colour += ka * Ia
    Vec3 kd{0.0f};           ///< Lambert diffuse reflectance (I_d = I0 kd cos α)
    Vec3 ks{0.0f};           ///< Phong specular reflectance (I_s = I0 ks cos^n γ)
    float shininess = 1.0f;  ///< Phong exponent n
    float reflectivity = 0;  ///< weight of the colour seen along the mirror direction
    float transparency = 0;  ///< weight of the colour seen along the refracted direction
    float ior = 1.0f;        ///< index of refraction of the inside (outside is 1)
    /// Radiance emitted from the front side of every surface with this material (a mesh or
    /// triangle becomes a light). Only light transport (--method path) sees it.
    Vec3 emission{0.0f};
    /// When set, ka and kd are multiplied by the texture's colour at the surface point
    /// (shading/material_eval.h, in every method).
    std::optional<Texture> texture;
    /// When set, ka is multiplied by this texture instead of `texture` (an MTL file's map_Ka).
    std::optional<Texture> ambient_texture;
    /// Set on the materials of meshes with vertex colours (TriangleSet::colors): ka and kd are
    /// multiplied by the colour interpolated at the surface point, as by a texture's.
    bool vertex_colours = false;
};

}  // namespace hikari
