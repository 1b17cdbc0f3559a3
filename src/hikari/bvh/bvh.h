#pragma once
// The triangle BVH as plain data: a binary tree in one flat array of nodes, plus the triangles
// copied in leaf order. `bvh_builder.h` makes one, `bvh_traversal.h` shoots rays through it.
//
// Layout choices, made with the wide (4/8-child, SIMD) BVH of later work in mind:
// - the two children of an inner node are adjacent, so a node names only its first child, and
//   collapsing to a wide BVH is pulling grandchildren up into one node;
// - leaves are contiguous runs of `triangles`, so a wide leaf can test several triangles at once;
// - triangles hold their three vertices exactly as given (not vertex + edges: recomputing
//   p0 + e1 rounds, and neighbours would no longer share bit-identical edges, which the
//   watertight test needs).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "hikari/core/aabb.h"
#include "hikari/core/vec.h"

namespace hikari {

/// No root-to-leaf path is longer than this many edges; the builder guarantees it, and the
/// traversal sizes its fixed stack by it.
inline constexpr uint32_t k_bvh_max_depth = 64;

/// One node of the binary BVH: 32 bytes, two per cache line.
struct alignas(32) BvhNode {
    Aabb bounds;                  ///< world-space box around every triangle below
    uint32_t index = 0;           ///< leaf: first slot in Bvh::triangles; inner: first child
                                  ///< (the second child is index + 1)
    uint16_t triangle_count = 0;  ///< leaf: number of triangles (at least 1); inner: 0
    uint8_t split_axis = 0;       ///< inner: 0, 1, 2 for x, y, z; the first child holds the
                                  ///< triangles with the smaller centroids along it
    uint8_t reserved = 0;         ///< always 0, so nodes compare and hash bytewise

    /// True for a leaf, false for an inner node.
    constexpr bool is_leaf() const { return triangle_count != 0; }
    constexpr bool operator==(const BvhNode&) const = default;
};
static_assert(sizeof(BvhNode) == 32);

/// A triangle's vertices, copied from the mesh in leaf order so that the hot loop reads them
/// contiguously instead of following the index array.
struct BvhTriangle {
    Vec3 p0, p1, p2;

    constexpr bool operator==(const BvhTriangle&) const = default;
};

/// A bounding volume hierarchy over a triangle mesh. Empty (no nodes) when the mesh had no
/// usable triangle; traversal then reports no hit.
struct Bvh {
    std::vector<BvhNode> nodes;          ///< nodes[0] is the root
    std::vector<BvhTriangle> triangles;  ///< the usable triangles, in leaf order
    std::vector<uint32_t> triangle_ids;  ///< triangle_ids[i]: index in the builder's input of
                                         ///< triangles[i]

    /// True when the tree holds no triangle.
    bool empty() const { return nodes.empty(); }
    /// Bounds of the whole tree; an empty box for an empty tree.
    Aabb bounds() const { return empty() ? Aabb{} : nodes[0].bounds; }
    /// Bytes held by nodes, triangles and ids (the memory target is 64 per triangle).
    size_t memory_bytes() const {
        return nodes.size() * sizeof(BvhNode) + triangles.size() * sizeof(BvhTriangle) +
               triangle_ids.size() * sizeof(uint32_t);
    }
};

}  // namespace hikari
