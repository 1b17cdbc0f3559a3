#pragma once
// Every light kind's sampling routine behind one call: sample_light(light, p) for a Light of
// any kind, at one point or at each lane's point. Dispatch is a switch over the variant's kinds,
// made by the compiler from the kind list (no virtual call per point).
//
// This one-sample form is the whole light for point and directional lights, and the centre of
// an area light (what a shadow map sees); area and environment lights are integrated over many
// samples by shading/light_integral.h.

#include <limits>
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

}  // namespace hikari
