#pragma once
// Light sources of the lecture ("CG でよく使われる光源"), a closed set dispatched by std::visit.

#include <cmath>
#include <limits>
#include <variant>

#include "hikari/core/vec.h"

namespace hikari {

/// Light from one point; irradiance falls off as intensity / d² (or not at all, as POV-Ray's
/// default light without fade).
struct PointLight {
    Vec3 position;
    Vec3 intensity;
    bool inverse_square = true;  ///< false: irradiance = intensity at any distance
};

/// Light from infinitely far away (the sun); no falloff.
struct DirectionalLight {
    Vec3 direction;  ///< unit direction in which the light travels (L_in), world space
    Vec3 intensity;
};

using Light = std::variant<PointLight, DirectionalLight>;

/// What one light delivers to one surface point.
struct LightSample {
    Vec3 to_light;    ///< unit direction from the point toward the light (L)
    float distance;   ///< distance to the light; infinity for directional lights
    Vec3 irradiance;  ///< I0 at the point, after falloff
};

/// Evaluates `light` at world-space point `p`.
inline LightSample sample_light(const Light& light, Vec3 p) {
    if (const auto* point = std::get_if<PointLight>(&light)) {
        const Vec3 d = point->position - p;
        const float d2 = dot(d, d);
        const float dist = std::sqrt(d2);
        return {d / dist, dist, point->inverse_square ? point->intensity / d2 : point->intensity};
    }
    const auto& dir = std::get<DirectionalLight>(light);
    return {-dir.direction, std::numeric_limits<float>::infinity(), dir.intensity};
}

}  // namespace hikari
