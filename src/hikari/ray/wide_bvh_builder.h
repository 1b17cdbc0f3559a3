#pragma once
// Building the wide BVH: a binned-SAH binary tree (bvh_builder.h) collapsed to eight children
// per node, the largest child opened first (Wald et al. 2008, Sec 3; Embree's BVH8 builder does
// the same), and the triangles rewritten into per-leaf structure-of-arrays blocks.

#include <array>
#include <cstdint>
#include <span>

#include "hikari/core/vec.h"
#include "hikari/ray/bvh.h"
#include "hikari/ray/bvh_builder.h"
#include "hikari/ray/wide_bvh.h"

namespace hikari {

/// The binary build settings for a wide tree: a node visit costs three triangle tests, as an
/// 8-wide leaf test costs about one node test; this gives bigger leaves, 55 instead of 62 bytes
/// per triangle on the bunny and 3-5% faster B1/B2 (docs/performance.md).
inline BvhBuildSettings wide_bvh_build_settings() {
    BvhBuildSettings settings;
    settings.traversal_cost = 3.0f;
    return settings;
}

/// Collapses a binary BVH into a wide one with the same leaves. Deterministic: the result
/// depends only on `binary`. Leaves of more than 16 triangles are not supported (throws).
WideBvh collapse_to_wide_bvh(const Bvh& binary);

/// Builds the binary tree with `settings` and collapses it (see build_bvh for what triangles
/// are left out). Identical for any thread count.
WideBvh build_wide_bvh(std::span<const Vec3> positions,
                       std::span<const std::array<uint32_t, 3>> indices,
                       const BvhBuildSettings& settings = wide_bvh_build_settings());

}  // namespace hikari
