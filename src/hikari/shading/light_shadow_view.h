#pragma once
// How a light is seen by the methods that see shadows from one place (shadow maps, shadow
// volumes, the analytic segment test): every light kind says it once (shading/lights/).

#include "hikari/core/vec.h"

namespace hikari {

/// The projection of a light's shadow map.
enum class ShadowProjection {
    none,      ///< no map: the light is integrated unshadowed (an environment light)
    parallel,  ///< one orthographic map along `direction` (a directional light)
    cube,  ///< six 90° perspective maps around `origin` (a point light, an area light's centre)
    cone,  ///< one perspective map from `origin` along `direction`, `half_angle` wide (a spot)
};

/// Where a light's shadows are cast from.
struct LightShadowView {
    ShadowProjection projection = ShadowProjection::none;
    Vec3 origin;           ///< the point the light is seen from (cube, cone)
    Vec3 direction;        ///< the travel direction (parallel) or the cone's unit axis (cone)
    float half_angle = 0;  ///< the cone's half-angle, degrees (cone)
    float radius = 0;      ///< the light's radius, for the penumbrae of PCSS (0: a point)
};

}  // namespace hikari
