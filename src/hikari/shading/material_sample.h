#pragma once
// A material evaluated at a surface point: what the shading model and Whitted's secondary rays
// read, for one point or for each lane of a pack (shading/material_eval.h fills it).

#include "hikari/core/lanes.h"
#include "hikari/core/vec.h"

namespace hikari {

/// The coefficients of the lecture's shading model at one point, texture applied, and the
/// weights of the mirror and refracted rays. Linear RGB.
template <class F>
struct MaterialSample {
    Vec3T<F> ka, kd, ks;  ///< ambient, Lambert diffuse and Phong specular reflectance
    /// The Phong exponent as phong_power raises it (phong_integer_exponent), or -1.
    IntOf<F> exponent = IntOf<F>(0);
    F shininess = F(1.0f);  ///< the Phong exponent n
    F reflectivity = F(0.0f), transparency = F(0.0f), ior = F(1.0f);
    /// Lanes whose material has no lane form (a Phong exponent only std::pow raises, a texture
    /// kind without one): their colour must come from the scalar code. Always false for float.
    MaskOf<F> scalar_only = MaskOf<F>(false);
};

}  // namespace hikari
