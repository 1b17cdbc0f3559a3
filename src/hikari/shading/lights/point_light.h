#pragma once
// The point light: the lecture's inverse-square falloff I0 / d², seen from one point. Every
// per-kind operation of shading/lights.h for it.

#include <numbers>
#include <optional>
#include <string_view>

#include "hikari/core/color.h"
#include "hikari/core/lanes.h"
#include "hikari/scene/light.h"
#include "hikari/shading/light_sample.h"
#include "hikari/shading/light_shadow_view.h"

namespace hikari {

/// What `light` delivers to world-space point `p`.
template <class F>
HIKARI_INLINE HIKARI_HD LightSampleT<F> sample_light(const PointLight& light, const Vec3T<F>& p) {
    const Vec3T<F> d = Vec3T<F>(light.position) - p;
    const F d2 = dot(d, d);
    const F distance = sqrt_of(d2);
    const Vec3T<F> intensity(light.intensity);
    // d / distance as Vec3's operator/ computes it: d · (1 / distance).
    return {d / distance, distance, light.inverse_square ? intensity / d2 : intensity};
}

/// One sample among many: a point light is the same every time.
inline LightSample sample_light_at(const PointLight& light, Vec3 p, Vec3, Vec2) {
    return sample_light<float>(light, p);
}

/// The path tracer's sample: the light itself, chosen with probability `choice`.
HIKARI_HD inline IncidentSample sample_incident(const PointLight& light, Vec3 p, Vec3, Vec2,
                                                float choice) {
    return delta_incident(sample_light<float>(light, p), choice);
}

/// No direction drawn by a BSDF meets a point.
HIKARI_HD inline float incident_pdf(const PointLight&, Vec3, Vec3, float, float) { return 0.0f; }

/// Φ = 4π·I (luminance), what it sends in all directions.
inline double light_power(const PointLight& light, float) {
    return 4.0 * std::numbers::pi_v<float> * luminance(light.intensity);
}

inline std::optional<Vec3> light_position(const PointLight& light) { return light.position; }

/// A cube map around the light.
inline LightShadowView shadow_view(const PointLight& light) {
    return {ShadowProjection::cube, light.position};
}

constexpr bool is_delta(const PointLight&) { return true; }
constexpr std::string_view light_kind_name(const PointLight&) { return "point"; }

/// No face: rays never meet a point light.
HIKARI_HD inline float face_hit(const PointLight&, Vec3, Vec3, float t_max) { return t_max; }
HIKARI_HD inline Vec3 face_radiance(const PointLight&) { return Vec3(0.0f); }
constexpr bool has_face(const PointLight&) { return false; }

}  // namespace hikari
