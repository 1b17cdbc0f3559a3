#pragma once
// Every light kind's sampling routine behind one call: sample_light(light, p) for a Light of
// any kind, at one point or at each lane's point. Dispatch is a switch over the variant's kinds,
// made by the compiler from the kind list (no virtual call per point).

#include "hikari/core/lanes.h"
#include "hikari/core/visit.h"
#include "hikari/scene/light.h"
#include "hikari/shading/light_sample.h"
#include "hikari/shading/lights/directional_light.h"
#include "hikari/shading/lights/point_light.h"

namespace hikari {

/// What `light` delivers to world-space point `p` (each lane's, for a pack).
template <class F>
HIKARI_INLINE LightSampleT<F> sample_light(const Light& light, const Vec3T<F>& p) {
    return visit_kind(light, [&](const auto& kind) { return sample_light<F>(kind, p); });
}

}  // namespace hikari
