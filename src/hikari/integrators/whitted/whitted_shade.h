#pragma once
// The shading step of the Whitted ray tracer for a whole block of hits at once: whitted.cpp runs
// it level by level over a tile's rays (a breadth-first "wavefront" of the ray tree, as in
// Boulos et al. 2007, "Packet-based Whitted and Distribution Ray Tracing") instead of recursing
// one ray at a time. The lanes run the generic code of whitted_surface.h on packs of
// k_lane_chunk lanes, so every lane's colour and rays are bit-identical to the one-ray code.
// Lanes whose material has no lane form (MaterialSample::scalar_only) are flagged for the caller
// to shade with the one-ray code.

#include <cstdint>

#include "hikari/core/block_lanes.h"
#include "hikari/core/simd_level.h"
#include "hikari/integrators/whitted/whitted_scene.h"
#include "hikari/scene/scene.h"

namespace hikari {

namespace detail {

/// Lanes per shading call: one block of rays (integrators/whitted/primary_hits.h).
inline constexpr int k_shade_lanes = k_primary_block_rays;
static_assert(k_shade_lanes % k_lane_chunk == 0);

/// The shading kernel for each SIMD level: fills the outputs (LaneChunk's "shading's results")
/// of every active lane of the chunks that hold one of the first `count` lanes, and the
/// secondary rays when `spawn` is nonzero. Lanes without a hit get only their colour: the sky's.
void shade_lanes_portable(const WhittedScene& scene, int spawn, int count, BlockLanes& lanes);
void shade_lanes_avx2(const WhittedScene& scene, int spawn, int count, BlockLanes& lanes);
void shade_lanes_avx512(const WhittedScene& scene, int spawn, int count, BlockLanes& lanes);

}  // namespace detail

/// Shades blocks of hits of one scene in lanes, with the kernel of the chosen SIMD level. Read
/// by all threads.
class LaneShader {
  public:
    /// `scene` (and the Scene it views) must outlive this object; `level` must be supported by
    /// this CPU.
    explicit LaneShader(const WhittedScene& scene, SimdLevel level = best_simd_level())
        : m_scene(scene), m_level(level) {}

    /// Shades every active lane among the first round_up(count, k_lane_chunk) of `lanes` (and
    /// spawns their secondary rays when `spawn`); the lanes past `count` in the last chunk must
    /// be marked inactive. The lanes' `lit` bits must hold their shadow rays' answers.
    void shade(detail::BlockLanes& lanes, int count, bool spawn) const;

  private:
    const WhittedScene& m_scene;
    SimdLevel m_level;
};

}  // namespace hikari
