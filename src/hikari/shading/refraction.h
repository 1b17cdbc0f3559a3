#pragma once
// Snell's law for the transmitted ray of Whitted ray tracing (the lecture's Fig 4.43).

#include <cmath>
#include <optional>

#include "hikari/core/vec.h"

namespace hikari {

/// Direction of the ray transmitted through a surface, or nothing on total internal reflection.
/// `incident` is the unit direction of travel, `n` the unit normal on the incident side
/// (dot(incident, n) ≤ 0) and `eta` = n_incident / n_transmitted. Snell: η_i sin θ_i = η_t sin θ_t.
inline std::optional<Vec3> refract(Vec3 incident, Vec3 n, float eta) {
    const float cos_i = -dot(incident, n);
    const float sin2_t = eta * eta * std::max(0.0f, 1.0f - cos_i * cos_i);
    if (sin2_t > 1.0f) return std::nullopt;  // total internal reflection
    const float cos_t = std::sqrt(1.0f - sin2_t);
    return normalize(eta * incident + (eta * cos_i - cos_t) * n);
}

}  // namespace hikari
