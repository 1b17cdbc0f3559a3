#pragma once
// The triangle BVH the ray tracer traverses: eight children per node, their boxes stored
// structure-of-arrays so one SIMD instruction tests all eight (Wald et al. 2008, "Getting rid of
// packets"; Ernst & Greiner 2008, "Multi bounding volume hierarchies"), and the triangles of
// each leaf stored structure-of-arrays so one SIMD watertight test covers a whole leaf.
// `wide_bvh_builder.h` makes one, `wide_bvh_traversal.h` and `wide_bvh_packet.h` shoot rays
// through it.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "hikari/core/aabb.h"
#include "hikari/core/host_device.h"
#include "hikari/core/huge_page_allocator.h"

namespace hikari {

/// Children per node: one 256-bit register of floats.
inline constexpr uint32_t k_wide_bvh_width = 8;

/// No chain of binned-SAH splits from the root to a leaf is longer than this; build_wide_bvh
/// guarantees it (halving ranges at the median near the limit). A root-to-leaf path has no more
/// wide nodes than splits, so the traversals size their fixed stacks by it.
inline constexpr uint32_t k_bvh_max_depth = 64;

/// Entries a traversal stack needs: at most k_wide_bvh_width - 1 deferred children per wide node
/// on the path to the current one, and the root.
inline constexpr uint32_t k_wide_bvh_stack_size = (k_wide_bvh_width - 1) * k_bvh_max_depth + 1;

/// A reference to a child of a wide node (or to the root): an inner node, a leaf, or nothing.
/// Leaves are encoded in place so the traversal needs no extra memory access to start one.
struct WideBvhRef {
    static constexpr uint32_t k_empty = 0xffffffffu;
    static constexpr uint32_t k_leaf_bit = 0x80000000u;
    static constexpr uint32_t k_count_shift = 27;                  ///< 4 bits: count - 1
    static constexpr uint32_t k_first_mask = (1u << 27) - 1;       ///< 27 bits: first triangle
    static constexpr uint32_t k_max_triangles = k_first_mask + 1;  ///< triangles a tree can hold
    static constexpr uint32_t k_max_leaf_size = 16;

    /// Encodes an inner node by its index in WideBvh::nodes.
    static constexpr uint32_t inner(uint32_t node) { return node; }
    /// Encodes a leaf over triangle slots [first, first + count), 1 <= count <= 16.
    static constexpr uint32_t leaf(uint32_t first, uint32_t count) {
        return k_leaf_bit | ((count - 1) << k_count_shift) | first;
    }
    static constexpr bool is_leaf(uint32_t ref) { return (ref & k_leaf_bit) != 0; }
    static constexpr uint32_t leaf_first(uint32_t ref) { return ref & k_first_mask; }
    static constexpr uint32_t leaf_count(uint32_t ref) {
        return ((ref >> k_count_shift) & 15u) + 1;
    }
};

/// One node: the boxes of up to eight children, structure-of-arrays. An unused slot has the
/// empty box (min +inf, max -inf), which every slab test rejects, and the child
/// WideBvhRef::k_empty.
struct alignas(32) WideBvhNode {
    /// bounds[2 a][i] is child i's minimum along axis a, bounds[2 a + 1][i] its maximum.
    std::array<std::array<float, k_wide_bvh_width>, 6> bounds;
    std::array<uint32_t, k_wide_bvh_width> child;  ///< WideBvhRef encodings
};
static_assert(sizeof(WideBvhNode) == 224);

/// A wide BVH over a triangle mesh. The triangles of a leaf over slots [first, first + count)
/// lie at triangle_data[9 first ...] as nine rows of `count` floats: p0.x, p0.y, p0.z, p1.x, ...,
/// p2.z, the vertices exactly as given (watertightness needs bit-identical shared edges).
struct WideBvh {
    HugePageVector<WideBvhNode> nodes;    ///< inner nodes; nodes[0] is the root when root is inner
    HugePageVector<float> triangle_data;  ///< per-leaf SoA vertices, plus 8 floats of padding so
                                          ///< 8-wide loads at a leaf's end stay inside
    HugePageVector<uint32_t> triangle_ids;  ///< triangle_ids[slot]: input index of that triangle
                                            ///< (of that box, for a tree built over boxes)
    uint32_t root = WideBvhRef::k_empty;    ///< the root reference (a leaf for tiny meshes)
    Aabb root_bounds;                       ///< box around every triangle

    /// True when the tree holds no triangle.
    bool empty() const { return root == WideBvhRef::k_empty; }
    /// Number of triangles held.
    size_t triangle_count() const { return triangle_ids.size(); }
    /// Bytes held by nodes, triangle data and ids (the target is at most 64 per triangle).
    size_t memory_bytes() const {
        return nodes.size() * sizeof(WideBvhNode) + triangle_data.size() * sizeof(float) +
               triangle_ids.size() * sizeof(uint32_t);
    }
};

/// Triangle i of a leaf's block (the `count` triangles at WideBvh::triangle_data[9 first ...]),
/// its vertices as given, for the reference tests.
HIKARI_HD inline void load_leaf_triangle(const float* block, uint32_t count, uint32_t i, Vec3& p0,
                                         Vec3& p1, Vec3& p2) {
    p0 = {block[0 * count + i], block[1 * count + i], block[2 * count + i]};
    p1 = {block[3 * count + i], block[4 * count + i], block[5 * count + i]};
    p2 = {block[6 * count + i], block[7 * count + i], block[8 * count + i]};
}

}  // namespace hikari
