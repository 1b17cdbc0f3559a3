#pragma once
// Every light kind's sampling routine behind one call: sample_light(light, p) for a Light of
// any kind, at one point or at each lane's point. Dispatch is a switch over the variant's kinds,
// made by the compiler from the kind list (no virtual call per point).
//
// This one-sample form is the whole light for point and directional lights, and the centre of
// an area light (what a shadow map sees); area and environment lights are integrated over many
// samples by shading/light_integral.h.

#include <algorithm>
#include <limits>
#include <optional>
#include <span>
#include <type_traits>

#include "hikari/core/lanes.h"
#include "hikari/core/visit.h"
#include "hikari/scene/light.h"
#include "hikari/shading/light_sample.h"
#include "hikari/shading/lights/area_light.h"
#include "hikari/shading/lights/directional_light.h"
#include "hikari/shading/lights/environment_light.h"
#include "hikari/shading/lights/point_light.h"

namespace hikari {

/// What `light` delivers to world-space point `p` (each lane's, for a pack). An environment
/// light has no one direction: it delivers nothing here (light_integral.h samples it).
template <class F>
HIKARI_INLINE LightSampleT<F> sample_light(const Light& light, const Vec3T<F>& p) {
    return visit_kind(light, [&](const auto& kind) {
        if constexpr (std::is_same_v<std::decay_t<decltype(kind)>, EnvironmentLight>)
            return LightSampleT<F>{Vec3T<F>(Vec3(0, 1, 0)),
                                   F(std::numeric_limits<float>::infinity()), Vec3T<F>(0.0f)};
        else
            return sample_light<F>(kind, p);
    });
}

/// Where a ray meets an area light's face: which light of the list, and at what distance.
struct LightFaceHit {
    size_t light = 0;
    float t = 0;
};

/// The nearest area light's face among `lights` that a ray from `origin` along unit `direction`
/// meets strictly before `t_max` (either side of a two-sided light, else its emitting side).
inline std::optional<LightFaceHit> nearest_light_face(std::span<const Light> lights, Vec3 origin,
                                                      Vec3 direction, float t_max) {
    std::optional<LightFaceHit> nearest;
    for (size_t l = 0; l < lights.size(); ++l) {
        const auto* area = std::get_if<AreaLight>(&lights[l]);
        if (!area) continue;
        const float t = area_light_hit(*area, origin, direction, t_max);
        if (t == t_max) continue;
        t_max = t;
        nearest = LightFaceHit{l, t};
    }
    return nearest;
}

/// The radiance a ray from `origin` along unit `direction` meets at the nearest area light's
/// face among `lights` strictly before `t_max` (what camera, mirror and refracted rays see of
/// the lights in every method), if it meets one.
inline std::optional<Vec3> light_face_seen(std::span<const Light> lights, Vec3 origin,
                                           Vec3 direction, float t_max) {
    const std::optional<LightFaceHit> hit = nearest_light_face(lights, origin, direction, t_max);
    if (!hit) return std::nullopt;
    return std::get<AreaLight>(lights[hit->light]).radiance;
}

/// Whether some light among `lights` is an area light (whose face rays can meet).
inline bool has_area_light(std::span<const Light> lights) {
    return std::any_of(lights.begin(), lights.end(),
                       [](const Light& l) { return std::holds_alternative<AreaLight>(l); });
}

/// The scene's environment light among `lights`, or null (a scene has at most one).
inline const EnvironmentLight* find_environment(std::span<const Light> lights) {
    for (const Light& light : lights)
        if (const auto* env = std::get_if<EnvironmentLight>(&light)) return env;
    return nullptr;
}

}  // namespace hikari
