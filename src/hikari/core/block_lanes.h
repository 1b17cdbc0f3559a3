#pragma once
// The lanes of a block of rays, structure-of-arrays from the ray to its shaded colour: the one
// layout that the Whitted tracer's front end (integrators/whitted/primary_hits.h: rays, nearest
// hits, shadow rays) and its shading step (integrators/whitted/whitted_shade.h) both read and
// write, so a hit never leaves the lanes between being found and being shaded (Wald et al. 2001 and
// Boulos et al. 2007 keep packets of rays, hits and shading in SIMD-friendly arrays the same way).
//
// A block holds up to 16 x 16 rays in chunks of 16 lanes. For camera rays chunk c is row c of
// the block's pixels and lane j its column; for any other rays (mirror, refracted) lane k is ray
// k. The kernels loop over one chunk's arrays at a time: a constant trip count and arrays at
// constant offsets from one another are what g++ 12 needs to vectorise a loop without run-time
// alias checks.

#include <cstddef>
#include <cstdint>

#include "hikari/core/lanes.h"
#include "hikari/core/vec.h"

namespace hikari {

/// Edge of the largest block of camera rays traced at once, in pixels.
inline constexpr int k_primary_block = 16;
/// Rays in a full block.
inline constexpr int k_primary_block_rays = k_primary_block * k_primary_block;
/// Lanes the kernels compute together (one row of a block of camera rays).
inline constexpr int k_lane_chunk = 16;
/// Lanes that hold `count` rays: count rounded up to whole chunks.
constexpr int lanes_for(int count) {
    return (count + k_lane_chunk - 1) / k_lane_chunk * k_lane_chunk;
}
/// The most lights whose shadow rays a block traces (one bit each in LaneChunk::lit); with
/// more, the Whitted tracer shades the block's hits with the one-ray code.
inline constexpr size_t k_max_block_lights = 32;

namespace detail {

/// Chunks in a block.
inline constexpr int k_block_chunks = k_primary_block_rays / k_lane_chunk;

/// Sixteen rays and everything found about them, one array per quantity. A lane with `active`
/// 0 holds no hit: its hit fields are zero (or, before the front end has run, anything) and no
/// output of it is read.
struct alignas(64) LaneChunk {
    // The rays: set by the camera kernel or from the caller's rays.
    float origin[3][k_lane_chunk];
    float direction[3][k_lane_chunk];  ///< unit length

    // Their nearest hits (integrators/whitted/primary_hits.h): SceneIntersector::closest's answer,
    // bit for bit.
    float t[k_lane_chunk];  ///< in: nearest triangle t or ∞; out: nearest t
    /// 0 none, 1 triangle, 2 + i sphere i, 2 + spheres + j plane j.
    int32_t object[k_lane_chunk];
    int32_t active[k_lane_chunk];             ///< 1 where the ray hit something
    float position[3][k_lane_chunk];          ///< hit point
    float geometric_normal[3][k_lane_chunk];  ///< as SurfaceHit has it (not turned)
    float shading_normal[3][k_lane_chunk];
    int32_t material[k_lane_chunk];
    uint32_t id[k_lane_chunk];  ///< PrimitiveId of the primitive hit
    /// Triangle hits (object 1): the triangle's index and the weights of its corners 1 and 2,
    /// for texture coordinates.
    uint32_t triangle[k_lane_chunk];
    float bary[2][k_lane_chunk];
    int32_t lit[k_lane_chunk];  ///< bit l: the shadow ray toward light l is unblocked

    // The hits' shadow rays toward one light at a time (scratch of the front end).
    float shadow_origin[3][k_lane_chunk];     ///< offset off the surface
    float shadow_direction[3][k_lane_chunk];  ///< unit direction toward the light
    float shadow_distance[k_lane_chunk];      ///< distance to the light (∞: directional)
    int32_t blocked[k_lane_chunk];            ///< 1 where a casting sphere or plane blocks

    // Shading's results (integrators/whitted/whitted_shade.h).
    float colour[3][k_lane_chunk];      ///< local illumination (ambient + lit lights), or sky
    int32_t shadow_rays[k_lane_chunk];  ///< lights facing the point (shadow rays cast)
    int32_t scalar_only[k_lane_chunk];  ///< 1: colour must be recomputed by the one-ray code
    /// Only with spawning: weight of the mirror and refracted rays (0: no such ray) and the rays.
    float mirror_weight[k_lane_chunk];
    float refract_weight[k_lane_chunk];
    float mirror_origin[3][k_lane_chunk];
    float mirror_direction[3][k_lane_chunk];
    float refract_origin[3][k_lane_chunk];
    float refract_direction[3][k_lane_chunk];
    int32_t children[k_lane_chunk];  ///< secondary rays the lane spawns (0, 1 or 2)
};

/// A block's lanes: lane k is entry k % k_lane_chunk of chunk k / k_lane_chunk.
struct BlockLanes {
    LaneChunk chunks[k_block_chunks];

    LaneChunk& chunk(int lane) { return chunks[lane / k_lane_chunk]; }
    const LaneChunk& chunk(int lane) const { return chunks[lane / k_lane_chunk]; }
};

/// Lane k's index inside its chunk.
constexpr int lane_in_chunk(int lane) { return lane % k_lane_chunk; }

/// Whether any lane of the chunk holds a hit.
inline bool any_active(const LaneChunk& chunk) {
    int32_t any = 0;
    for (const int32_t active : chunk.active) any |= active;
    return any != 0;
}

/// Lanes [first, first + width) of three lane arrays (x, y, z) as a vector of packs.
template <class Isa>
HIKARI_INLINE Vec3T<LaneFloat<Isa>> load_lanes(const float (&a)[3][k_lane_chunk], int first) {
    static_assert(k_lane_chunk % Isa::k_width == 0);
    return {LaneFloat<Isa>::load(a[0] + first), LaneFloat<Isa>::load(a[1] + first),
            LaneFloat<Isa>::load(a[2] + first)};
}

/// A vector of packs into lanes [first, first + width) of three lane arrays.
template <class Isa>
HIKARI_INLINE void store_lanes(const Vec3T<LaneFloat<Isa>>& v, float (&a)[3][k_lane_chunk],
                               int first) {
    v.x.store(a[0] + first), v.y.store(a[1] + first), v.z.store(a[2] + first);
}

}  // namespace detail

}  // namespace hikari
