#pragma once
// Every light kind's operations behind one call each, for a Light of any kind: the ray tracer,
// the path tracer, the raster shading pass, the shadow passes and explain all call these. Each
// is an exhaustive visit (visit_light) calling the function of the same name in the kind's own
// file in shading/lights/: a kind whose file lacks one fails to compile here. Dispatch is a
// switch over the variant's kinds, made by the compiler from the kind list (no virtual call per
// point).
//
// sample_light's one-sample form is the whole light for point, spot and directional lights, and
// the centre of an area light (what a shadow map sees); area and environment lights are
// integrated over many samples (sample_light_at) by shading/light_integral.h.

#include <algorithm>
#include <optional>
#include <span>
#include <string_view>

#include "hikari/core/lanes.h"
#include "hikari/core/visit.h"
#include "hikari/scene/light.h"
#include "hikari/shading/light_sample.h"
#include "hikari/shading/light_shadow_view.h"
#include "hikari/shading/lights/area_light.h"
#include "hikari/shading/lights/directional_light.h"
#include "hikari/shading/lights/environment_light.h"
#include "hikari/shading/lights/point_light.h"
#include "hikari/shading/lights/spot_light.h"

namespace hikari {

/// What `light` delivers to world-space point `p` (each lane's, for a pack). An environment
/// light has no one direction: it delivers nothing here (sample_light_at samples it).
template <class F>
HIKARI_INLINE HIKARI_HD LightSampleT<F> sample_light(const Light& light, const Vec3T<F>& p) {
    return visit_light(light, [&](const auto& kind) { return sample_light<F>(kind, p); });
}

/// One of many stratified samples of `light` at point `p` with unit normal `n`, for the point
/// `uv` of the unit square: uniform over an area light, by importance over an environment, the
/// light itself for the others.
inline LightSample sample_light_at(const Light& light, Vec3 p, Vec3 n, Vec2 uv) {
    return visit_light(light, [&](const auto& kind) { return sample_light_at(kind, p, n, uv); });
}

/// The path tracer's light sample at `p` (unit normal `n`) for the pair `u`, its pdf times
/// `choice`, the probability of having chosen the light.
HIKARI_HD inline IncidentSample sample_incident(const Light& light, Vec3 p, Vec3 n, Vec2 u,
                                                float choice) {
    return visit_light(light,
                       [&](const auto& kind) { return sample_incident(kind, p, n, u, choice); });
}

/// The density (per steradian, times `choice`) with which sample_incident at a point with unit
/// normal `n` draws direction `dir`, meeting the light at distance `t` (multiple importance
/// sampling); 0 for delta lights.
HIKARI_HD inline float incident_pdf(const Light& light, Vec3 n, Vec3 dir, float t, float choice) {
    return visit_light(light,
                       [&](const auto& kind) { return incident_pdf(kind, n, dir, t, choice); });
}

/// An estimate of the power `light` sends into a scene within a sphere of radius
/// `scene_radius` (lights at infinity by what crosses its disc), by luminance.
inline double light_power(const Light& light, float scene_radius) {
    return visit_light(light, [&](const auto& kind) { return light_power(kind, scene_radius); });
}

/// The point `light` sits at, for a scene's bounds: a point or spot light's position, an area
/// light's centre; none for lights at infinity.
inline std::optional<Vec3> light_position(const Light& light) {
    return visit_light(light, [](const auto& kind) { return light_position(kind); });
}

/// Where `light`'s shadow maps and shadow volumes see it from.
inline LightShadowView shadow_view(const Light& light) {
    return visit_light(light, [](const auto& kind) { return shadow_view(kind); });
}

/// Whether `light` is one point or one direction (point, spot, directional), which a single
/// shadow ray or shadow-map lookup answers; area and environment lights are integrated over many.
HIKARI_HD inline bool is_delta_light(const Light& light) {
    return visit_light(light, [](const auto& kind) { return is_delta(kind); });
}

/// The word scene files use for `light`'s kind.
inline std::string_view light_kind_name(const Light& light) {
    return visit_light(light, [](const auto& kind) { return light_kind_name(kind); });
}

/// Where a ray meets an area light's face: which light of the list, and at what distance.
struct LightFaceHit {
    size_t light = 0;
    float t = 0;
};

/// The nearest light face among the `count` lights at `lights` (an area light's) that a ray
/// from `origin` along unit `direction` meets strictly before `t_max` (either side of a
/// two-sided light, else its emitting side): whether there is one, and which into `nearest`.
HIKARI_HD inline bool find_light_face(const Light* lights, size_t count, Vec3 origin,
                                      Vec3 direction, float t_max, LightFaceHit& nearest) {
    bool found = false;
    for (size_t l = 0; l < count; ++l) {
        const float t = visit_light(
            lights[l], [&](const auto& kind) { return face_hit(kind, origin, direction, t_max); });
        if (t == t_max) continue;
        t_max = t;
        nearest = LightFaceHit{l, t};
        found = true;
    }
    return found;
}

/// The nearest light face among `lights` (find_light_face), if a ray meets one.
inline std::optional<LightFaceHit> nearest_light_face(std::span<const Light> lights, Vec3 origin,
                                                      Vec3 direction, float t_max) {
    LightFaceHit nearest;
    if (!find_light_face(lights.data(), lights.size(), origin, direction, t_max, nearest))
        return std::nullopt;
    return nearest;
}

/// The radiance of light `light`'s face (what a ray that meets it sees).
HIKARI_HD inline Vec3 face_radiance(const Light& light) {
    return visit_light(light, [](const auto& kind) { return face_radiance(kind); });
}

/// The radiance a ray from `origin` along unit `direction` meets at the nearest light face among
/// `lights` strictly before `t_max` (what camera, mirror and refracted rays see of the lights in
/// every method), if it meets one.
inline std::optional<Vec3> light_face_seen(std::span<const Light> lights, Vec3 origin,
                                           Vec3 direction, float t_max) {
    const std::optional<LightFaceHit> hit = nearest_light_face(lights, origin, direction, t_max);
    if (!hit) return std::nullopt;
    return face_radiance(lights[hit->light]);
}

/// Whether some light among `lights` has a face rays can meet (an area light).
inline bool has_area_light(std::span<const Light> lights) {
    return std::any_of(lights.begin(), lights.end(), [](const Light& l) {
        return visit_light(l, [](const auto& kind) { return has_face(kind); });
    });
}

/// `light` as the kind `Kind`, or null when it is another kind: for what one kind alone has (an
/// environment's sky, an area light's closed-form soft shadows).
template <class Kind>
const Kind* light_as(const Light& light) {
    return visit_light(light, Overloaded{[](const Kind& k) -> const Kind* { return &k; },
                                         [](const auto&) -> const Kind* { return nullptr; }});
}

/// The scene's environment light among `lights`, or null (a scene has at most one).
inline const EnvironmentLight* find_environment(std::span<const Light> lights) {
    for (const Light& light : lights)
        if (const auto* env = light_as<EnvironmentLight>(light)) return env;
    return nullptr;
}

}  // namespace hikari
