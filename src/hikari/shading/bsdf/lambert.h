#pragma once
// Lambert's diffuse reflection made a BRDF for light transport: the lecture's I·kd·cos α becomes
// f = kd / π, so that a white (kd = 1) surface reflects all the light it receives:
// ∫ (1/π) cos θ dω = 1 over the hemisphere. Sampled by the cosine (Malley's method), which
// makes f·cos θ / pdf = kd for every direction.

#include <cmath>
#include <numbers>

#include "hikari/core/host_device.h"
#include "hikari/core/orthonormal_basis.h"
#include "hikari/core/vec.h"

namespace hikari {

/// A direction about +z with density cos θ / π, for the point `u` of the unit square: a
/// uniform point of the unit disc lifted onto the hemisphere (its z is cos θ).
HIKARI_HD inline Vec3 cosine_hemisphere_local(Vec2 u) {
    constexpr float k_two_pi = 2.0f * std::numbers::pi_v<float>;
    const float r = std::sqrt(u.x), phi = k_two_pi * u.y;
    const float cos_theta = std::sqrt(std::max(0.0f, 1.0f - u.x));
    return {r * std::cos(phi), r * std::sin(phi), cos_theta};
}

/// The same about unit `n`.
HIKARI_HD inline Vec3 cosine_hemisphere_direction(Vec3 n, Vec2 u) {
    return OrthonormalBasis(n).to_world(cosine_hemisphere_local(u));
}

/// The density of cosine_hemisphere_direction for a direction at cos θ from its normal.
HIKARI_HD inline float cosine_hemisphere_pdf(float cos_theta) {
    return cos_theta > 0.0f ? cos_theta * std::numbers::inv_pi_v<float> : 0.0f;
}

/// f of the Lambert lobe with albedo kd (the same for every pair of directions above the
/// surface).
HIKARI_HD inline Vec3 lambert_brdf(Vec3 kd) { return kd * std::numbers::inv_pi_v<float>; }

}  // namespace hikari
