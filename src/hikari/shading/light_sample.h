#pragma once
// What a light delivers to a surface point: the answer of every light kind's sampling routine
// (shading/lights/), generic over the number type (core/lanes.h).

#include "hikari/core/lanes.h"
#include "hikari/core/vec.h"

namespace hikari {

/// What one light delivers to one surface point (or to each lane's point).
template <class F>
struct LightSampleT {
    Vec3T<F> to_light;    ///< unit direction from the point toward the light (L)
    F distance;           ///< distance to the light; infinity for lights at infinity
    Vec3T<F> irradiance;  ///< I0 at the point, after falloff
};

using LightSample = LightSampleT<float>;

}  // namespace hikari
