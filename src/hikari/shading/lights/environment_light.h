#pragma once
// The environment light's sampling routine. Light arrives from every direction ω with radiance
// L(ω), so a point receives ∫ L(ω)·(reflection term) dω over the hemisphere above it. One
// sample direction ω drawn with density pdf(ω) stands for L(ω) / pdf(ω):
// - a constant radiance is sampled by the cosine about the normal (pdf cos θ / π), which makes
//   the diffuse term exact with every sample: kd·L·π;
// - a map by its texels' luminance · sin θ (scene/environment_map.h), so bright regions such as
//   the sun get the samples.
// Every per-kind operation of shading/lights.h for it.

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string_view>

#include "hikari/core/color.h"
#include "hikari/core/lanes.h"
#include "hikari/core/orthonormal_basis.h"
#include "hikari/core/vec.h"
#include "hikari/scene/light.h"
#include "hikari/shading/bsdf/lambert.h"
#include "hikari/shading/light_sample.h"
#include "hikari/shading/light_shadow_view.h"

namespace hikari {

/// One direction of the environment toward the sky from a point with unit normal `n`, for the
/// random pair (u, v) in [0, 1)²: irradiance L(ω) / pdf(ω) (zero where the direction carries no
/// light), at infinite distance.
inline LightSample sample_environment(const EnvironmentLight& light, Vec3 n, float u, float v) {
    constexpr float k_pi = std::numbers::pi_v<float>;
    constexpr float k_far = std::numeric_limits<float>::infinity();
    if (!light.map) {
        const Vec3 local = cosine_hemisphere_local({u, v});
        const float cos_theta = local.z;
        const Vec3 dir = OrthonormalBasis(n).to_world(local);
        if (!(cos_theta > 0.0f)) return {dir, k_far, Vec3(0.0f)};
        return {dir, k_far, light.radiance * (k_pi / cos_theta)};
    }
    const EnvironmentDirection s = light.map->sample({u, v});
    if (!(s.pdf > 0.0f)) return {s.direction, k_far, Vec3(0.0f)};
    return {s.direction, k_far, light.radiance * s.radiance / s.pdf};
}

/// An environment light has no one direction: as a single sample it delivers nothing (it is
/// integrated over many, sample_light_at).
template <class F>
HIKARI_INLINE HIKARI_HD LightSampleT<F> sample_light(const EnvironmentLight&, const Vec3T<F>&) {
    return {Vec3T<F>(Vec3(0, 1, 0)), F(std::numeric_limits<float>::infinity()), Vec3T<F>(0.0f)};
}

/// One stratified sample among many at a point with unit normal `n`.
inline LightSample sample_light_at(const EnvironmentLight& light, Vec3, Vec3 n, Vec2 uv) {
    return sample_environment(light, n, uv.x, uv.y);
}

/// Whether `light` has a map (false on the GPU: the map's tables are host arrays, and the
/// kernels refuse mapped environments, so a device only ever sees a constant one).
HIKARI_HD inline bool has_environment_map(const EnvironmentLight& light) {
#if HIKARI_DEVICE_PASS
    return false;
#else
    return light.map != nullptr;
#endif
}

/// The path tracer's sample: a map's direction by its importance density, a constant sky's by
/// the cosine about `n`; pdf times `choice`.
HIKARI_HD inline IncidentSample sample_incident(const EnvironmentLight& light, Vec3, Vec3 n, Vec2 u,
                                                float choice) {
    IncidentSample s;
    s.distance = std::numeric_limits<float>::infinity();
    if (has_environment_map(light)) {
#if !HIKARI_DEVICE_PASS
        const EnvironmentDirection d = light.map->sample(u);
        s.to_light = d.direction;
        if (!(d.pdf > 0.0f)) return s;
        s.radiance = light.radiance * d.radiance;
        s.pdf = choice * d.pdf;
#endif
    } else {
        s.to_light = cosine_hemisphere_direction(n, u);
        const float pdf = cosine_hemisphere_pdf(dot(n, s.to_light));
        if (!(pdf > 0.0f)) return s;
        s.radiance = light.radiance;
        s.pdf = choice * pdf;
    }
    return s;
}

/// The density with which sample_incident draws `dir` at a point with unit normal `n`.
HIKARI_HD inline float incident_pdf(const EnvironmentLight& light, Vec3 n, Vec3 dir, float,
                                    float choice) {
    float pdf = 0.0f;
    if (has_environment_map(light)) {
#if !HIKARI_DEVICE_PASS
        pdf = light.map->pdf(dir);
#endif
    } else {
        pdf = cosine_hemisphere_pdf(dot(n, dir));
    }
    return choice * pdf;
}

/// The mean luminance of the light's radiance over all directions.
inline float mean_luminance(const EnvironmentLight& light) {
    if (!light.map) return luminance(light.radiance);
    const Image& image = light.map->image();
    double sum = 0.0, weight = 0.0;
    for (int y = 0; y < image.height; ++y) {
        const double sin_theta = std::sin(std::numbers::pi_v<float> * (y + 0.5) / image.height);
        for (int x = 0; x < image.width; ++x) {
            sum += sin_theta * luminance(image.at(x, y));
            weight += sin_theta;
        }
    }
    return weight > 0.0 ? luminance(light.radiance) * static_cast<float>(sum / weight) : 0.0f;
}

/// What crosses the disc of the scene's bounding sphere from every side: π² r² L̄.
inline double light_power(const EnvironmentLight& light, float scene_radius) {
    constexpr float k_pi = std::numbers::pi_v<float>;
    return k_pi * k_pi * scene_radius * scene_radius * mean_luminance(light);
}

inline std::optional<Vec3> light_position(const EnvironmentLight&) { return std::nullopt; }

/// No map: the environment lights every method unshadowed or by its own sampled shadow rays.
inline LightShadowView shadow_view(const EnvironmentLight&) { return {}; }

constexpr bool is_delta(const EnvironmentLight&) { return false; }
constexpr std::string_view light_kind_name(const EnvironmentLight&) { return "environment"; }

/// Escaping rays see it (the methods' backdrop), not a face.
HIKARI_HD inline float face_hit(const EnvironmentLight&, Vec3, Vec3, float t_max) { return t_max; }
HIKARI_HD inline Vec3 face_radiance(const EnvironmentLight&) { return Vec3(0.0f); }
constexpr bool has_face(const EnvironmentLight&) { return false; }

}  // namespace hikari
