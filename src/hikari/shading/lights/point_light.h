#pragma once
// The point light's sampling routine: the lecture's inverse-square falloff I0 / d².

#include "hikari/core/lanes.h"
#include "hikari/scene/light.h"
#include "hikari/shading/light_sample.h"

namespace hikari {

/// What `light` delivers to world-space point `p`.
template <class F>
HIKARI_INLINE LightSampleT<F> sample_light(const PointLight& light, const Vec3T<F>& p) {
    const Vec3T<F> d = Vec3T<F>(light.position) - p;
    const F d2 = dot(d, d);
    const F distance = sqrt_of(d2);
    const Vec3T<F> intensity(light.intensity);
    // d / distance as Vec3's operator/ computes it: d · (1 / distance).
    return {d / distance, distance, light.inverse_square ? intensity / d2 : intensity};
}

}  // namespace hikari
