#pragma once
// Building the wide BVH straight from the triangles: binned SAH (Wald 2007) splits, each node's
// largest child split again until it has eight (Wald et al. 2008, Sec 3; Embree's BVH8 builder,
// Wald et al. 2014, does the same), leaves written straight into their structure-of-arrays
// blocks. Collapsing a binary tree (bvh_builder.h) is kept for comparison and tests.

#include <array>
#include <cstdint>
#include <span>

#include "hikari/bvh/bvh.h"
#include "hikari/bvh/bvh_builder.h"
#include "hikari/bvh/wide_bvh.h"
#include "hikari/core/vec.h"

namespace hikari {

/// The binary build settings for a wide tree (collapse_to_wide_bvh(build_bvh(...))): a node
/// visit costs three triangle tests, as an 8-wide leaf test costs about one node test; this
/// gives bigger leaves, 55 instead of 62 bytes per triangle on the bunny and 3-5% faster B1/B2
/// (docs/performance.md). build_wide_bvh uses bin_count, max_leaf_size and parallel_threshold.
inline BvhBuildSettings wide_bvh_build_settings() {
    BvhBuildSettings settings;
    settings.traversal_cost = 3.0f;
    return settings;
}

/// Collapses a binary BVH into a wide one with the same leaves. Deterministic: the result
/// depends only on `binary`. Leaves of more than 16 triangles are not supported (throws).
WideBvh collapse_to_wide_bvh(const Bvh& binary);

/// Builds the wide tree over the triangles `indices` (three vertex indices each, into
/// `positions`); triangles build_bvh would leave out are left out. Every range of at most
/// settings.max_leaf_size (at most 16) triangles becomes a leaf, larger ones split at the best
/// binned-SAH plane; ranges of more than settings.parallel_threshold triangles are built as
/// parallel tasks, and binned and partitioned in parallel above four times that. Identical for
/// any thread count. Throws std::length_error for WideBvhRef::k_max_triangles triangles or more.
WideBvh build_wide_bvh(std::span<const Vec3> positions,
                       std::span<const std::array<uint32_t, 3>> indices,
                       const BvhBuildSettings& settings = wide_bvh_build_settings());

}  // namespace hikari
