#pragma once
// A smooth dielectric boundary (glass, water): light is reflected with the Fresnel reflectance F
// and refracted by Snell's law with the rest, 1 − F (the lecture's Fig 4.43 gives the two
// directions; Whitted weighted them by fixed coefficients, light transport by Fresnel's).

#include <algorithm>
#include <cmath>

#include "hikari/core/host_device.h"
#include "hikari/core/vec.h"

namespace hikari {

/// The unpolarized Fresnel reflectance of a smooth boundary for light arriving at cos θ_i > 0
/// from the side of index n_i, with `eta` = n_i / n_t; 1 under total internal reflection.
/// Also gives cos θ_t, the transmitted direction's angle with the normal.
HIKARI_HD inline float fresnel_dielectric(float cos_i, float eta, float& cos_t) {
    const float sin2_t = eta * eta * std::max(0.0f, 1.0f - cos_i * cos_i);
    if (sin2_t >= 1.0f) {
        cos_t = 0.0f;
        return 1.0f;
    }
    cos_t = std::sqrt(1.0f - sin2_t);
    // The s- and p-polarized amplitudes with both indices divided by n_t.
    const float r_s = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    const float r_p = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5f * (r_s * r_s + r_p * r_p);
}

/// The direction refracted from `to_eye` (unit, on the side of unit normal `n`) into the other
/// side, given eta = n_i / n_t and cos θ_t from fresnel_dielectric.
HIKARI_HD inline Vec3 refracted_direction(Vec3 to_eye, Vec3 n, float eta, float cos_t) {
    const float cos_i = dot(to_eye, n);
    return normalize(-eta * to_eye + (eta * cos_i - cos_t) * n);
}

}  // namespace hikari
