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

namespace hikari {

/// One light sample as the path tracer weighs it (Veach 1997, multiple importance sampling):
/// the radiance arriving along `to_light` and the density with which it was drawn.
struct IncidentSample {
    Vec3 to_light;        ///< unit direction from the point toward the light
    float distance = 0;   ///< to the sampled point; infinity for directions
    Vec3 radiance{0.0f};  ///< L arriving from there (for a delta light: its irradiance)
    float pdf = 0;        ///< per steradian times the caller's `choice` (the probability of
                          ///< choosing the light); for a delta light, `choice` alone
    bool delta = false;   ///< a light at one point or in one direction: no BSDF sample finds it
};

/// A light at one point or in one direction, chosen with probability `choice`, as the path
/// tracer's sample: all of what it delivers, from its one direction.
HIKARI_HD inline IncidentSample delta_incident(const LightSample& light, float choice) {
    return {light.to_light, light.distance, light.irradiance, choice, true};
}

}  // namespace hikari
