#pragma once
// Building the wide BVH straight from the triangles: binned SAH (Wald 2007, "On fast construction
// of SAH-based bounding volume hierarchies") splits, each node's largest child split again until
// it has eight (Wald et al. 2008, Sec 3; Embree's BVH8 builder, Wald et al. 2014, does the same),
// leaves written straight into their structure-of-arrays blocks. Parallel over subtrees, binning
// and partition with oneTBB, and identical for any thread count.

#include <array>
#include <cstdint>
#include <span>

#include "hikari/bvh/wide_bvh.h"
#include "hikari/core/aabb.h"
#include "hikari/core/vec.h"

namespace hikari {

/// Knobs of the BVH build; the defaults suit primary and shadow rays on ordinary meshes.
struct BvhBuildSettings {
    /// Bins per axis; the SAH is evaluated at the bin_count - 1 planes between them
    /// (clamped to [2, 32]; Wald 2007 finds 16 to 32 as good as a full sweep). Ranges of fewer
    /// triangles get fewer bins (at least 4).
    uint32_t bin_count = 16;
    /// Every range of at most this many triangles becomes one leaf, and no leaf holds more
    /// (clamped to [1, WideBvhRef::k_max_leaf_size]): the 8-wide leaf test costs about the same
    /// for 1 to 8 triangles.
    uint32_t max_leaf_size = 8;
    /// Ranges with more triangles than this are built as parallel tasks, and binned and
    /// partitioned in parallel above four times that; smaller ones are built serially.
    uint32_t parallel_threshold = 4096;
};

/// Builds the wide tree over bounded primitives given by their boxes (spheres, any shape with a
/// box): leaves over slots of WideBvh::triangle_ids, which hold the index into `boxes` of each
/// primitive, and no triangle_data (the caller lays out its primitives by slot). Empty or
/// non-finite boxes are left out. Deterministic and limited as the triangle build.
WideBvh build_wide_bvh_over_boxes(std::span<const Aabb> boxes,
                                  const BvhBuildSettings& settings = {});

/// Builds the wide tree over the triangles `indices` (three vertex indices each, into
/// `positions`). Triangles with an index out of range, a non-finite vertex or zero area are left
/// out (they could never be hit); WideBvh::triangle_ids keeps the input index of every other one.
/// The tree depends only on the input and the settings, never on the number of threads. Throws
/// std::length_error for WideBvhRef::k_max_triangles triangles or more.
WideBvh build_wide_bvh(std::span<const Vec3> positions,
                       std::span<const std::array<uint32_t, 3>> indices,
                       const BvhBuildSettings& settings = {});

}  // namespace hikari
