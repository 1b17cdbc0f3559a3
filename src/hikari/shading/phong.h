#pragma once
// The lecture's one shading model (Fig 4.29), written once and used by every method:
//   colour = ka Ia + Σ_lights I (kd max(0, N·L) + ks max(0, R·V)^n)
// with R = L_in + 2aN, a = −L_in·N, where L_in is the light's direction of travel.

#include <cmath>
#include <cstdint>

#include "hikari/core/vec.h"
#include "hikari/scene/material.h"

namespace hikari {

/// The ambient term ka·Ia ("環境光": light bounced so often it lights everything evenly).
inline Vec3 shade_ambient(const Material& m, Vec3 ambient_intensity) {
    return m.ka * ambient_intensity;
}

/// The largest Phong exponent phong_power raises by repeated squaring.
inline constexpr int32_t k_max_integer_exponent = 1024;

/// The Phong exponent n as the integer phong_power raises by repeated squaring (n an integer in
/// [0, k_max_integer_exponent]), or -1 where it calls std::pow instead.
inline int32_t phong_integer_exponent(float n) {
    if (!(n >= 0.0f && n <= static_cast<float>(k_max_integer_exponent)) ||
        n != static_cast<float>(static_cast<unsigned>(n)))
        return -1;
    return static_cast<int32_t>(n);
}

/// cos^n for the Phong highlight. Integer exponents up to 1024 (the usual case) by repeated
/// squaring, much cheaper than pow(): each squaring doubles the relative rounding error, so the
/// result is within about n·2^-24 relative (1e-5 for n = 200, far below 8-bit output steps).
/// Other exponents go through std::pow.
inline float phong_power(float cos_gamma, float n) {
    const int32_t exponent = phong_integer_exponent(n);
    if (exponent < 0) return std::pow(cos_gamma, n);
    float result = 1.0f, base = cos_gamma;
    for (auto e = static_cast<unsigned>(exponent); e != 0; e >>= 1, base *= base)
        if (e & 1u) result *= base;
    return result;
}

/// Light from one source reflected toward the eye: Lambert diffuse I0 kd cos α plus Phong
/// specular I0 ks cos^n γ. All vectors are unit length and world space: `n` the surface normal
/// facing the viewer, `to_light` (L) from the point toward the light, `to_eye` (V) from the point
/// toward the eye; `irradiance` is I0 at the point (after 1/d² falloff). There is no specular
/// where N·L ≤ 0: light arriving from behind the surface cannot make a highlight.
inline Vec3 shade_direct(const Material& m, Vec3 n, Vec3 to_light, Vec3 to_eye, Vec3 irradiance) {
    const float cos_alpha = dot(n, to_light);
    if (cos_alpha <= 0.0f) return Vec3(0.0f);
    // R = L_in + 2aN with L_in = −L and a = −L_in·N = N·L: the mirror direction of the light.
    const Vec3 r = reflect(-to_light, n);
    const float cos_gamma = dot(r, to_eye);
    const float specular = cos_gamma > 0.0f ? phong_power(cos_gamma, m.shininess) : 0.0f;
    return irradiance * (m.kd * cos_alpha + m.ks * specular);
}

}  // namespace hikari
