#pragma once
// The Whitted shading step over a block's lanes (whitted_shade.h), compiled by whitted_shade.cpp
// (baseline x86-64), whitted_shade_avx2.cpp and whitted_shade_avx512.cpp after their
// `#pragma GCC target`. There is no shading code here: each chunk of lanes is loaded into packs
// (core/lanes.h) and handed to the same generic functions the one-ray path instantiates for
// float (whitted_surface.h), so both round alike. `KernelIsa` has internal linkage, which gives
// every function instantiated on these packs internal linkage too: each file keeps its own.

#include <cstdint>

#include "hikari/core/block_lanes.h"
#include "hikari/core/lanes.h"
#include "hikari/integrators/whitted/whitted_shade.h"
#include "hikari/integrators/whitted/whitted_surface.h"

namespace hikari::detail {
namespace {

struct KernelIsa {};
using LaneF = LaneFloat<KernelIsa>;
using LaneI = LaneInt<KernelIsa>;
using LaneM = LaneMask<KernelIsa>;
/// The chunk's hits as shading reads them. Lanes without a hit take the first hit's material:
/// one material fewer to evaluate in chunks that are partly sky.
HIKARI_INLINE WhittedHit<LaneF> load_hits(const LaneChunk& lanes, const LaneM& active) {
    WhittedHit<LaneF> hit;
    hit.direction = load_lanes<KernelIsa>(lanes.direction);
    hit.position = load_lanes<KernelIsa>(lanes.position);
    hit.geometric_normal = load_lanes<KernelIsa>(lanes.geometric_normal);
    hit.shading_normal = load_lanes<KernelIsa>(lanes.shading_normal);
    const LaneI material = LaneI::load(lanes.material);
    const int32_t first = material[__builtin_ctz(lane_bits(active))];
    hit.material = select(active, material, LaneI(first));
    return hit;
}

/// The secondary rays of the chunk's lanes (their weights only, where there are none).
HIKARI_INLINE void store_secondary(const SecondaryRays<LaneF>& rays, LaneChunk& lanes) {
    rays.mirror_weight.store(lanes.mirror_weight);
    rays.refract_weight.store(lanes.refract_weight);
    if (!any((rays.mirror_weight > LaneF(0.0f)) | (rays.refract_weight > LaneF(0.0f)))) return;
    store_lanes<KernelIsa>(rays.mirror_origin, lanes.mirror_origin);
    store_lanes<KernelIsa>(rays.mirror_direction, lanes.mirror_direction);
    store_lanes<KernelIsa>(rays.refract_origin, lanes.refract_origin);
    store_lanes<KernelIsa>(rays.refract_direction, lanes.refract_direction);
}

/// One chunk with at least one hit: local illumination (the shadow rays' answers are the front
/// end's lit bits), then the secondary rays when `spawn`.
HIKARI_INLINE void shade_chunk(const WhittedScene& scene, int spawn, LaneChunk& lanes) {
    const LaneM active = LaneM::load(lanes.active);
    const WhittedHit<LaneF> hit = load_hits(lanes, active);
    const LaneI lit = LaneI::load(lanes.lit);
    const auto visible = [&](size_t light, const LightSampleT<LaneF>&, const SurfacePoint<LaneF>&,
                             const LaneM&) { return (lit & LaneI(1 << light)) != LaneI(0); };
    const WhittedShading<LaneF> shaded = shade_whitted_hit<LaneF>(scene, hit, active, visible);
    store_lanes<KernelIsa>(shaded.direct.colour, lanes.colour);
    shaded.direct.tested.store(lanes.shadow_rays);
    (active & shaded.material.scalar_only).store(lanes.scalar_only);
    store_secondary(
        spawn ? whitted_secondary_rays(shaded, hit.direction, active) : SecondaryRays<LaneF>{},
        lanes);
}

/// What rays that hit nothing see, in the lanes without a hit.
HIKARI_INLINE void sky_chunk(const WhittedScene& scene, LaneChunk& lanes) {
    const LaneM active = LaneM::load(lanes.active);
    const Vec3T<LaneF> sky =
        scene.sky->colour_toward(load_lanes<KernelIsa>(lanes.direction), scene.background);
    store_lanes<KernelIsa>(select(active, load_lanes<KernelIsa>(lanes.colour), sky), lanes.colour);
}

/// Every chunk that holds one of the first `count` lanes: shading where a lane has a hit, the
/// sky's colour where not, and every lane's count of shadow rays, scalar flag and children
/// (zero where no hit).
[[maybe_unused]] void shade_kernel(const WhittedScene& scene, int spawn, int count,
                                   BlockLanes& lanes) {
    for (int c = 0; c * k_lane_chunk < count; ++c) {
        LaneChunk& chunk = lanes.chunks[c];
        if (any_active(chunk)) {
            shade_chunk(scene, spawn, chunk);
        } else {
            LaneI(0).store(chunk.shadow_rays);
            LaneI(0).store(chunk.scalar_only);
            LaneF(0.0f).store(chunk.mirror_weight);
            LaneF(0.0f).store(chunk.refract_weight);
        }
        const LaneI children = mask_to_int(LaneF::load(chunk.mirror_weight) > LaneF(0.0f)) +
                               mask_to_int(LaneF::load(chunk.refract_weight) > LaneF(0.0f));
        children.store(chunk.children);
        sky_chunk(scene, chunk);
    }
}

}  // namespace
}  // namespace hikari::detail
