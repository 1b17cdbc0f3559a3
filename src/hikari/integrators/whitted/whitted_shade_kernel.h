#pragma once
// The Whitted shading step over a block's lanes (whitted_shade.h), compiled by whitted_shade.cpp
// (baseline x86-64), whitted_shade_avx2.cpp and whitted_shade_avx512.cpp after their
// `#pragma GCC target`. There is no shading code here: each chunk of lanes is loaded into packs
// of the target's width (core/lanes.h, core/kernel_isa.h) and handed to the same generic
// functions the one-ray path instantiates for float (whitted_surface.h), so both round alike.

#include <cstdint>

#include "hikari/core/block_lanes.h"
#include "hikari/core/kernel_isa.h"
#include "hikari/core/lanes.h"
#include "hikari/integrators/whitted/whitted_shade.h"
#include "hikari/integrators/whitted/whitted_surface.h"

namespace hikari::detail {
namespace {

/// Lanes [first, first + k_width) of a chunk's hits as shading reads them. Lanes without a hit
/// take the first hit's material: one material fewer to evaluate where some lanes see the sky.
HIKARI_INLINE WhittedHit<LaneF> load_hits(const LaneChunk& lanes, int first, const LaneM& active) {
    WhittedHit<LaneF> hit;
    hit.direction = load_lanes<KernelIsa>(lanes.direction, first);
    hit.position = load_lanes<KernelIsa>(lanes.position, first);
    hit.geometric_normal = load_lanes<KernelIsa>(lanes.geometric_normal, first);
    hit.shading_normal = load_lanes<KernelIsa>(lanes.shading_normal, first);
    const LaneI material = LaneI::load(lanes.material + first);
    const int32_t filler = material[__builtin_ctz(lane_bits(active))];
    hit.material = select(active, material, LaneI(filler));
    return hit;
}

/// The secondary rays of lanes [first, first + k_width) (their weights only, where none).
HIKARI_INLINE void store_secondary(const SecondaryRays<LaneF>& rays, int first, LaneChunk& lanes) {
    rays.mirror_weight.store(lanes.mirror_weight + first);
    rays.refract_weight.store(lanes.refract_weight + first);
    if (!any((rays.mirror_weight > LaneF(0.0f)) | (rays.refract_weight > LaneF(0.0f)))) return;
    store_lanes<KernelIsa>(rays.mirror_origin, lanes.mirror_origin, first);
    store_lanes<KernelIsa>(rays.mirror_direction, lanes.mirror_direction, first);
    store_lanes<KernelIsa>(rays.refract_origin, lanes.refract_origin, first);
    store_lanes<KernelIsa>(rays.refract_direction, lanes.refract_direction, first);
}

/// Lanes [first, first + k_width) of a chunk: where a lane has a hit, its local illumination
/// (the shadow rays' answers are the front end's lit bits), then its secondary rays when
/// `spawn`; where none, zero rays and weights.
HIKARI_INLINE void shade_pack(const WhittedScene& scene, int spawn, int first, LaneChunk& lanes) {
    const LaneM active = LaneM::load(lanes.active + first);
    if (!any(active)) {
        LaneI(0).store(lanes.shadow_rays + first);
        LaneI(0).store(lanes.scalar_only + first);
        LaneF(0.0f).store(lanes.mirror_weight + first);
        LaneF(0.0f).store(lanes.refract_weight + first);
        return;
    }
    const WhittedHit<LaneF> hit = load_hits(lanes, first, active);
    const LaneI lit = LaneI::load(lanes.lit + first);
    const auto visible = [&](size_t light, const LightSampleT<LaneF>&, const SurfacePoint<LaneF>&,
                             const LaneM&) {
        return ((lit >> static_cast<int>(light)) & LaneI(1)) != LaneI(0);
    };
    const WhittedShading<LaneF> shaded = shade_whitted_hit<LaneF>(scene, hit, active, visible);
    store_lanes<KernelIsa>(shaded.direct.colour, lanes.colour, first);
    shaded.direct.tested.store(lanes.shadow_rays + first);
    (active & shaded.material.scalar_only).store(lanes.scalar_only + first);
    store_secondary(
        spawn ? whitted_secondary_rays(shaded, hit.direction, active) : SecondaryRays<LaneF>{},
        first, lanes);
}

/// What rays that hit nothing see, in lanes [first, first + k_width) without a hit; and every
/// lane's count of children.
HIKARI_INLINE void finish_pack(const WhittedScene& scene, int first, LaneChunk& lanes) {
    const LaneM active = LaneM::load(lanes.active + first);
    const Vec3T<LaneF> sky =
        scene.sky->colour_toward(load_lanes<KernelIsa>(lanes.direction, first), scene.background);
    store_lanes<KernelIsa>(select(active, load_lanes<KernelIsa>(lanes.colour, first), sky),
                           lanes.colour, first);
    const LaneI children = mask_to_int(LaneF::load(lanes.mirror_weight + first) > LaneF(0.0f)) +
                           mask_to_int(LaneF::load(lanes.refract_weight + first) > LaneF(0.0f));
    children.store(lanes.children + first);
}

/// Every chunk that holds one of the first `count` lanes, a pack at a time: shading where a
/// lane has a hit, the sky's colour where not, and every lane's count of shadow rays, scalar
/// flag and children (zero where no hit).
[[maybe_unused]] void shade_kernel(const WhittedScene& scene, int spawn, int count,
                                   BlockLanes& lanes) {
    for (int c = 0; c * k_lane_chunk < count; ++c)
        for (int first = 0; first < k_lane_chunk; first += k_width) {
            shade_pack(scene, spawn, first, lanes.chunks[c]);
            finish_pack(scene, first, lanes.chunks[c]);
        }
}

}  // namespace
}  // namespace hikari::detail
