#pragma once
// The environment light's sampling routine. Light arrives from every direction ω with radiance
// L(ω), so a point receives ∫ L(ω)·(reflection term) dω over the hemisphere above it. One
// sample direction ω drawn with density pdf(ω) stands for L(ω) / pdf(ω):
// - a constant radiance is sampled by the cosine about the normal (pdf cos θ / π), which makes
//   the diffuse term exact with every sample: kd·L·π;
// - a map by its texels' luminance · sin θ (scene/environment_map.h), so bright regions such as
//   the sun get the samples.

#include <cmath>
#include <limits>
#include <numbers>

#include "hikari/core/orthonormal_basis.h"
#include "hikari/core/vec.h"
#include "hikari/scene/light.h"
#include "hikari/shading/bsdf/lambert.h"
#include "hikari/shading/light_sample.h"

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

}  // namespace hikari
