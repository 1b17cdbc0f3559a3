#pragma once
// The raster shading lanes (raster/shade_lanes.h), compiled by shade_lanes.cpp (baseline
// x86-64), shade_lanes_avx2.cpp and shade_lanes_avx512.cpp after their `#pragma GCC target`.
// No shading code lives here: each group of lanes is loaded into packs of the target's width
// (core/lanes.h, core/kernel_isa.h) and handed to the generic material and lighting code that
// the one-point pass instantiates for float.

#include <cstdint>

#include "hikari/core/kernel_isa.h"
#include "hikari/core/lanes.h"
#include "hikari/raster/shade_lanes.h"
#include "hikari/shading/direct.h"
#include "hikari/shading/material_eval.h"

namespace hikari::detail {
namespace {

static_assert(SurfaceLanes::k_lane_group % k_width == 0);

using LaneArray = float[SurfaceLanes::k_capacity];

HIKARI_INLINE Vec3T<LaneF> load3(const LaneArray (&a)[3], int first) {
    return {LaneF::load(a[0] + first), LaneF::load(a[1] + first), LaneF::load(a[2] + first)};
}

/// Lanes [first, first + k_width): the surface point, its material, its lights.
HIKARI_INLINE void shade_pack(const LaneLighting& lighting, int first, int count,
                              SurfaceLanes& lanes) {
    LaneI index;
    for (int k = 0; k < k_width; ++k) index.v[k] = first + k;
    const LaneM active = index < LaneI(count);
    SurfacePoint<LaneF> s;
    s.position = load3(lanes.position, first);
    s.normal = load3(lanes.normal, first);
    s.geometric_normal = s.normal;
    s.to_eye = load3(lanes.to_eye, first);
    s.u = LaneF::load(lanes.u + first), s.v = LaneF::load(lanes.v + first);
    s.du_dx = LaneF::load(lanes.du_dx + first), s.dv_dx = LaneF::load(lanes.dv_dx + first);
    s.du_dy = LaneF::load(lanes.du_dy + first), s.dv_dy = LaneF::load(lanes.dv_dy + first);
    s.dp_dx = load3(lanes.dp_dx, first), s.dp_dy = load3(lanes.dp_dy, first);
    const MaterialSample<LaneF> m =
        evaluate_material<LaneF>(lighting.materials, LaneI::load(lanes.material + first), s);
    const auto visible = [&](size_t light, const LightSampleT<LaneF>&, const SurfacePoint<LaneF>&,
                             const LaneM& facing) {
        if (!lighting.fractions) return LaneF(1.0f);
        alignas(64) float fraction[k_width] = {};
        lighting.fractions(lighting.context, light, first, lane_bits(facing), fraction);
        return LaneF::load(fraction);
    };
    const DirectLighting<LaneF> lit =
        direct_lighting<LaneF>(lighting.lighting, s, m, active, visible);
    lit.colour.x.store(lanes.colour[0] + first);
    lit.colour.y.store(lanes.colour[1] + first);
    lit.colour.z.store(lanes.colour[2] + first);
    (active & m.scalar_only).store(lanes.scalar_only + first);
}

[[maybe_unused]] void shade_lanes_kernel(const LaneLighting& lighting, int count,
                                         SurfaceLanes& lanes) {
    for (int first = 0; first < count; first += k_width) shade_pack(lighting, first, count, lanes);
}

}  // namespace
}  // namespace hikari::detail
