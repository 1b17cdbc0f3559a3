#pragma once
// The lecture's Phong highlight ks·cos^n γ made an energy-conserving BRDF (Lafortune & Willems
// 1994, "Using the modified Phong reflectance model for physically based rendering"):
//   f = ks · (n + 2) / (2π) · cos^n α,
// α the angle between the incoming direction and the mirror direction of the outgoing one. The
// factor (n + 2) / 2π makes the reflected fraction exactly ks for light arriving along the
// normal and less at any other angle (part of the lobe then falls below the horizon), so a lobe
// with ks ≤ 1 never reflects more than it receives. Sampled about the mirror direction with
// density (n + 1) / 2π · cos^n α (directions under the surface are drawn, and count zero).

#include <cmath>
#include <numbers>

#include "hikari/core/host_device.h"
#include "hikari/core/orthonormal_basis.h"
#include "hikari/core/vec.h"
#include "hikari/shading/phong.h"

namespace hikari {

/// The mirror direction of `to_eye` about unit `n` (the lobe's axis).
HIKARI_HD inline Vec3 phong_lobe_axis(Vec3 to_eye, Vec3 n) { return reflect(-to_eye, n); }

/// cos^n α between `wi` and the lobe's axis; 0 beyond 90°. `exponent` is
/// phong_integer_exponent(n) (shading/phong.h).
HIKARI_HD inline float phong_lobe_power(Vec3 axis, Vec3 wi, int32_t exponent, float n) {
    const float cos_alpha = dot(axis, wi);
    return cos_alpha > 0.0f ? phong_power<float>(cos_alpha, exponent, n) : 0.0f;
}

/// f of the normalized Phong lobe for cos^n α = `power`.
HIKARI_HD inline Vec3 normalized_phong_brdf(Vec3 ks, float n, float power) {
    return ks * ((n + 2.0f) * 0.5f * std::numbers::inv_pi_v<float> * power);
}

/// The sampling density for cos^n α = `power`, per steradian.
HIKARI_HD inline float normalized_phong_pdf(float n, float power) {
    return (n + 1.0f) * 0.5f * std::numbers::inv_pi_v<float> * power;
}

/// A direction about `axis` with density (n + 1)/2π · cos^n α, for the point `u` of the unit
/// square: cos α = u.x^(1/(n+1)), the azimuth uniform.
HIKARI_HD inline Vec3 normalized_phong_direction(Vec3 axis, float n, Vec2 u) {
    constexpr float k_two_pi = 2.0f * std::numbers::pi_v<float>;
    const float cos_alpha = std::pow(u.x, 1.0f / (n + 1.0f));
    const float sin_alpha = std::sqrt(std::max(0.0f, 1.0f - cos_alpha * cos_alpha));
    const float phi = k_two_pi * u.y;
    return OrthonormalBasis(axis).to_world(
        {sin_alpha * std::cos(phi), sin_alpha * std::sin(phi), cos_alpha});
}

}  // namespace hikari
