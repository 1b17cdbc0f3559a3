#pragma once
// Building the triangle BVH: binned SAH (Wald 2007, "On fast construction of SAH-based bounding
// volume hierarchies"), parallel over subtrees with oneTBB, identical for any thread count.

#include <array>
#include <cstdint>
#include <span>

#include "hikari/bvh/bvh.h"
#include "hikari/core/vec.h"

namespace hikari {

/// Knobs of the BVH build; the defaults suit primary and shadow rays on ordinary meshes.
struct BvhBuildSettings {
    /// Bins per axis; the SAH is evaluated at the bin_count - 1 planes between them
    /// (clamped to [2, 32]; Wald 2007 finds 16 to 32 as good as a full sweep).
    uint32_t bin_count = 16;
    /// Ranges of at most this many triangles always become leaves (at least 1).
    uint32_t min_leaf_size = 1;
    /// No leaf holds more triangles than this (clamped to [min_leaf_size, 255]), even when the
    /// SAH would prefer one.
    uint32_t max_leaf_size = 8;
    /// SAH cost of visiting one node, in units of one ray-triangle test. Higher values give
    /// bigger leaves, fewer nodes and less memory; 2 keeps nodes + triangles under 64 bytes per
    /// triangle on scanned and tessellated meshes (Stanford bunny: 63) at about 5% of speed.
    float traversal_cost = 2.0f;
    /// Ranges with more triangles than this are binned with a parallel reduction and their two
    /// halves built as parallel tasks; smaller ones are built serially. (build_wide_bvh: see
    /// there.)
    uint32_t parallel_threshold = 4096;
};

/// Builds a BVH over the triangles `indices` (three vertex indices each, into `positions`).
/// Triangles with an index out of range, a non-finite vertex or zero area are left out (they
/// could never be hit); Bvh::triangle_ids keeps the input index of every other one. The tree
/// depends only on the input and the settings, never on the number of threads.
Bvh build_bvh(std::span<const Vec3> positions, std::span<const std::array<uint32_t, 3>> indices,
              const BvhBuildSettings& settings = {});

}  // namespace hikari
