#pragma once
// Snell's law for the transmitted ray of Whitted ray tracing (the lecture's Fig 4.43), generic
// over the number type.

#include <optional>

#include "hikari/core/lanes.h"
#include "hikari/core/vec.h"

namespace hikari {

/// The transmitted direction and where there is none.
template <class F>
struct Refraction {
    Vec3T<F> direction;          ///< unit; meaningless where total_internal
    MaskOf<F> total_internal{};  ///< no transmitted ray: total internal reflection
};

/// The ray transmitted through a surface. `incident` is the unit direction of travel, `n` the
/// unit normal on the incident side (dot(incident, n) ≤ 0) and `eta` = n_incident /
/// n_transmitted. Snell: η_i sin θ_i = η_t sin θ_t.
template <class F>
HIKARI_INLINE HIKARI_HD Refraction<F> refract_ray(const Vec3T<F>& incident, const Vec3T<F>& n,
                                                  F eta) {
    const F cos_i = -dot(incident, n);
    const F sin2_i = F(1.0f) - cos_i * cos_i;
    // std::max(0, sin2_i), NaN included.
    const F sin2_t = eta * eta * select(F(0.0f) < sin2_i, sin2_i, F(0.0f));
    const F cos_t = sqrt_of(F(1.0f) - sin2_t);
    const Vec3T<F> t = incident * eta + n * (eta * cos_i - cos_t);
    return {t * (F(1.0f) / sqrt_of(dot(t, t))), sin2_t > F(1.0f)};
}

/// The scalar form: the direction, or nothing on total internal reflection.
HIKARI_INLINE HIKARI_HD std::optional<Vec3> refract(Vec3 incident, Vec3 n, float eta) {
    const Refraction<float> r = refract_ray<float>(incident, n, eta);
    if (r.total_internal) return std::nullopt;
    return r.direction;
}

}  // namespace hikari
