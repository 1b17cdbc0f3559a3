#pragma once
// The directional light's sampling routine: the same direction and irradiance everywhere.

#include <limits>

#include "hikari/core/lanes.h"
#include "hikari/scene/light.h"
#include "hikari/shading/light_sample.h"

namespace hikari {

/// What `light` delivers to any point: light from -direction, at infinite distance.
template <class F>
HIKARI_INLINE LightSampleT<F> sample_light(const DirectionalLight& light, const Vec3T<F>&) {
    return {Vec3T<F>(-light.direction), F(std::numeric_limits<float>::infinity()),
            Vec3T<F>(light.intensity)};
}

}  // namespace hikari
