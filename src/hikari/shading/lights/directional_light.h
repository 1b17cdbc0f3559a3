#pragma once
// The directional light: the same direction and irradiance everywhere (the sun). Every per-kind
// operation of shading/lights.h for it.

#include <limits>
#include <numbers>
#include <optional>
#include <string_view>

#include "hikari/core/color.h"
#include "hikari/core/lanes.h"
#include "hikari/scene/light.h"
#include "hikari/shading/light_sample.h"
#include "hikari/shading/light_shadow_view.h"

namespace hikari {

/// What `light` delivers to any point: light from -direction, at infinite distance.
template <class F>
HIKARI_INLINE HIKARI_HD LightSampleT<F> sample_light(const DirectionalLight& light,
                                                     const Vec3T<F>&) {
    return {Vec3T<F>(-light.direction), F(std::numeric_limits<float>::infinity()),
            Vec3T<F>(light.intensity)};
}

inline LightSample sample_light_at(const DirectionalLight& light, Vec3 p, Vec3, Vec2) {
    return sample_light<float>(light, p);
}

HIKARI_HD inline IncidentSample sample_incident(const DirectionalLight& light, Vec3 p, Vec3, Vec2,
                                                float choice) {
    return delta_incident(sample_light<float>(light, p), choice);
}

HIKARI_HD inline float incident_pdf(const DirectionalLight&, Vec3, Vec3, float, float) {
    return 0.0f;
}

/// What crosses the disc of the scene's bounding sphere (radius `scene_radius`): π r² E.
inline double light_power(const DirectionalLight& light, float scene_radius) {
    return std::numbers::pi_v<float> * scene_radius * scene_radius * luminance(light.intensity);
}

/// At infinity: no point of the scene's bounds.
inline std::optional<Vec3> light_position(const DirectionalLight&) { return std::nullopt; }

/// One orthographic map along the light's rays.
inline LightShadowView shadow_view(const DirectionalLight& light) {
    return {ShadowProjection::parallel, Vec3(0.0f), light.direction};
}

constexpr bool is_delta(const DirectionalLight&) { return true; }
constexpr std::string_view light_kind_name(const DirectionalLight&) { return "directional"; }

HIKARI_HD inline float face_hit(const DirectionalLight&, Vec3, Vec3, float t_max) { return t_max; }
HIKARI_HD inline Vec3 face_radiance(const DirectionalLight&) { return Vec3(0.0f); }
constexpr bool has_face(const DirectionalLight&) { return false; }

}  // namespace hikari
