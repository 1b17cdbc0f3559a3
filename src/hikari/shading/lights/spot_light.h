#pragma once
// The spot light: the lecture's point light (I / d²) restricted to a cone about its axis, with
// a smooth edge (scene/light.h):
//   E(p) = I · s(cos θ) / d²,  s(c) = t²(3 − 2t),  t = clamp((c − cos θo) / (cos θi − cos θo), 0,
//   1)
// θ the angle between the axis and p − position, θi and θo the inner and outer half-angles.
// Every per-kind operation of shading/lights.h for it.

#include <cmath>
#include <numbers>
#include <optional>
#include <string_view>

#include "hikari/core/color.h"
#include "hikari/core/lanes.h"
#include "hikari/scene/light.h"
#include "hikari/shading/light_sample.h"
#include "hikari/shading/light_shadow_view.h"

namespace hikari {

/// cos of an angle in degrees.
HIKARI_HD inline float cos_degrees(float degrees) {
    return std::cos(degrees * (std::numbers::pi_v<float> / 180.0f));
}

/// The cone's falloff s(c) at c = cos θ (each lane's): 1 inside the inner cone, 0 outside the
/// outer one, the smoothstep of c between; a hard edge at cos θo when the two are equal.
template <class F>
HIKARI_INLINE HIKARI_HD F spot_falloff(const SpotLight& light, const F& cos_theta) {
    const float cos_inner = cos_degrees(light.inner_angle);
    const float cos_outer = cos_degrees(light.outer_angle);
    if (!(cos_inner > cos_outer)) return select(cos_theta >= F(cos_outer), F(1.0f), F(0.0f));
    F t = (cos_theta - F(cos_outer)) / F(cos_inner - cos_outer);
    t = select(t < F(0.0f), F(0.0f), t);
    t = select(t > F(1.0f), F(1.0f), t);
    return t * t * (F(3.0f) - F(2.0f) * t);
}

/// What `light` delivers to world-space point `p`.
template <class F>
HIKARI_INLINE HIKARI_HD LightSampleT<F> sample_light(const SpotLight& light, const Vec3T<F>& p) {
    const Vec3T<F> d = Vec3T<F>(light.position) - p;
    const F d2 = dot(d, d);
    const F distance = sqrt_of(d2);
    const Vec3T<F> to_light = d / distance;
    const F cos_theta = -dot(to_light, Vec3T<F>(light.direction));
    return {to_light, distance, Vec3T<F>(light.intensity) * (spot_falloff(light, cos_theta) / d2)};
}

inline LightSample sample_light_at(const SpotLight& light, Vec3 p, Vec3, Vec2) {
    return sample_light<float>(light, p);
}

HIKARI_HD inline IncidentSample sample_incident(const SpotLight& light, Vec3 p, Vec3, Vec2,
                                                float choice) {
    return delta_incident(sample_light<float>(light, p), choice);
}

HIKARI_HD inline float incident_pdf(const SpotLight&, Vec3, Vec3, float, float) { return 0.0f; }

/// Φ = I ∫ s(cos θ) dω = 2π·I·(1 − (cos θi + cos θo) / 2): the full cone to θi, and half the
/// band between (the smoothstep is symmetric about its middle, so it averages 1/2 in c).
inline double light_power(const SpotLight& light, float) {
    const double band = 0.5 * (cos_degrees(light.inner_angle) + cos_degrees(light.outer_angle));
    return 2.0 * std::numbers::pi * luminance(light.intensity) * (1.0 - band);
}

inline std::optional<Vec3> light_position(const SpotLight& light) { return light.position; }

/// The widest cone one perspective shadow map covers well; wider spots take a cube map.
inline constexpr float k_max_cone_map_angle = 75.0f;

/// One perspective map of the cone from the light (Williams 1978's map from a spotlight); a
/// cube map about it when the cone is too wide for one.
inline LightShadowView shadow_view(const SpotLight& light) {
    if (light.outer_angle > k_max_cone_map_angle) return {ShadowProjection::cube, light.position};
    return {ShadowProjection::cone, light.position, light.direction, light.outer_angle};
}

constexpr bool is_delta(const SpotLight&) { return true; }
constexpr std::string_view light_kind_name(const SpotLight&) { return "spot"; }

HIKARI_HD inline float face_hit(const SpotLight&, Vec3, Vec3, float t_max) { return t_max; }
HIKARI_HD inline Vec3 face_radiance(const SpotLight&) { return Vec3(0.0f); }
constexpr bool has_face(const SpotLight&) { return false; }

}  // namespace hikari
