#pragma once
// Surface reflectance for the lecture's shading model (Fig 4.29) and Whitted's secondary rays.

#include <cmath>
#include <optional>
#include <string>

#include "hikari/core/vec.h"

namespace hikari {

/// A solid checker (POV-Ray's `checker` pattern): colour_a where
/// floor((x + offset.x) / size) + floor((y + offset.y) / size) + floor((z + offset.z) / size) is
/// even, colour_b where it is odd. Linear RGB.
struct CheckerTexture {
    float size = 1.0f;  ///< edge of one cube, world units (> 0)
    Vec3 color_a{1.0f};
    Vec3 color_b{0.0f};
    Vec3 offset{0.0f};  ///< added to the point first (moves the pattern by -offset)

    /// The colour at world-space point p.
    Vec3 at(Vec3 p) const {
        const Vec3 q = (p + offset) / size;
        const long long cell = floor_int(q.x) + floor_int(q.y) + floor_int(q.z);
        return (cell & 1) == 0 ? color_a : color_b;
    }

    /// floor(v) as an integer, without the libm call std::floor is on baseline x86-64 (no
    /// SSE4.1 round instruction): truncate, then step down for negative non-integers. Exact
    /// wherever the cast is defined (|v| < 2^63), since floats of 2^24 or more are integers.
    static long long floor_int(float v) {
        const auto truncated = static_cast<long long>(v);
        return truncated - (v < static_cast<float>(truncated) ? 1 : 0);
    }
};

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
    /// When set (ray tracing), ka and kd are multiplied by the texture's colour at the hit point.
    std::optional<CheckerTexture> texture;
};

}  // namespace hikari
