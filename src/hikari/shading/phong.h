#pragma once
// The lecture's one shading model (Fig 4.29), written once and used by every method:
//   colour = ka Ia + Σ_lights I (kd max(0, N·L) + ks max(0, R·V)^n)
// with R = L_in + 2aN, a = −L_in·N, where L_in is the light's direction of travel. Generic over
// the number type (core/lanes.h): one point, or each lane of a pack.

#include <bit>
#include <cmath>
#include <cstdint>

#include "hikari/core/lanes.h"
#include "hikari/core/vec.h"
#include "hikari/shading/light_sample.h"
#include "hikari/shading/material_sample.h"
#include "hikari/shading/surface.h"

namespace hikari {

/// The largest Phong exponent phong_power raises by repeated squaring.
inline constexpr int32_t k_max_integer_exponent = 1024;
/// Squaring steps of phong_power for any exponent up to k_max_integer_exponent.
inline constexpr int k_exponent_bits =
    std::bit_width(static_cast<unsigned>(k_max_integer_exponent));

/// The Phong exponent n as the integer phong_power raises by repeated squaring (n an integer in
/// [0, k_max_integer_exponent]), or -1 where it calls std::pow instead.
HIKARI_INLINE HIKARI_HD int32_t phong_integer_exponent(float n) {
    if (!(n >= 0.0f && n <= static_cast<float>(k_max_integer_exponent)) ||
        n != static_cast<float>(static_cast<unsigned>(n)))
        return -1;
    return static_cast<int32_t>(n);
}

/// cos^n for the Phong highlight, n = `exponent` (phong_integer_exponent of `shininess`).
/// Integer exponents up to 1024 (the usual case) by repeated squaring, much cheaper than pow():
/// each squaring doubles the relative rounding error, so the result is within about n·2^-24
/// relative (1e-5 for n = 200, far below 8-bit output steps). Always all k_exponent_bits steps:
/// past the top bit they leave the power as it is, and a constant count keeps lanes in step.
/// Other exponents go through std::pow, which has no lane form: a pack's lanes with exponent -1
/// are shaded by the scalar code instead (MaterialSample::scalar_only).
template <class F>
HIKARI_INLINE HIKARI_HD F phong_power(F cos_gamma, IntOf<F> exponent, F shininess) {
    if constexpr (k_is_scalar<F>)
        if (exponent < 0) return std::pow(cos_gamma, shininess);
    F power = F(1.0f), squared = cos_gamma;
    IntOf<F> bits = exponent;
    for (int b = 0; b < k_exponent_bits; ++b) {
        power = select((bits & IntOf<F>(1)) != IntOf<F>(0), power * squared, power);
        squared = squared * squared;
        bits = bits >> 1;
    }
    return power;
}

/// phong_power for a float exponent n.
HIKARI_INLINE HIKARI_HD float phong_power(float cos_gamma, float n) {
    return phong_power<float>(cos_gamma, phong_integer_exponent(n), n);
}

/// The specular factor max(0, R·V)^n, R the mirror direction of the light about the normal,
/// read literally: with n = 0 it is 1 wherever the light reaches the point (x⁰ = 1, also for
/// x = 0, as C's pow has it), not a disc where R·V > 0; for n > 0, 0 where R·V ≤ 0.
template <class F>
HIKARI_INLINE HIKARI_HD F phong_specular(const MaterialSample<F>& m, const SurfacePoint<F>& s,
                                         const Vec3T<F>& to_light) {
    // R = L_in + 2aN with L_in = −L and a = −L_in·N = N·L: the mirror direction of the light.
    const Vec3T<F> r = reflect(-to_light, s.normal);
    const F cos_gamma = dot(r, s.to_eye);
    if constexpr (k_is_scalar<F>)
        return phong_power(cos_gamma > 0.0f ? cos_gamma : 0.0f, m.exponent, m.shininess);
    else
        return phong_power(select(cos_gamma > F(0.0f), cos_gamma, F(0.0f)), m.exponent,
                           m.shininess);
}

/// Light from one source reflected toward the eye where it faces the surface (cos α = N·L > 0):
/// Lambert diffuse I0 kd cos α plus Phong specular I0 ks cos^n γ. `specular` false skips the
/// highlight where no lane's ks is nonzero (ks · anything = 0 then: the same bits).
template <class F>
HIKARI_INLINE HIKARI_HD Vec3T<F> phong_reflected(const MaterialSample<F>& m,
                                                 const SurfacePoint<F>& s,
                                                 const LightSampleT<F>& light, F cos_alpha,
                                                 bool specular) {
    const F spec = specular ? phong_specular(m, s, light.to_light) : F(0.0f);
    return light.irradiance * (m.kd * cos_alpha + m.ks * spec);
}

}  // namespace hikari
