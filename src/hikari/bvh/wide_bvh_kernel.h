#pragma once
// The wide-BVH traversal loop, written once as a template over the SIMD operations (`Ops`):
// the portable, AVX2 and AVX-512 kernels each instantiate it in their own translation unit,
// compiled for their instruction set. Internal to wide_bvh_traversal*.cpp.
//
// The loops are also templates over their leaves (`Leaves`, built once per ray): triangles
// (TriangleLeaves, the kernel's own SIMD test) or spheres (SphereLeaves, intersect_sphere), each
// providing
//   template <bool k_any_hit> bool test(uint32_t first, uint32_t count, Interval& valid,
//                                       LeafHit& hit)  -> Ops::LeafTest's contract, below
//   const void* address(uint32_t first) const -> where the leaf's data starts (prefetching)
//
// Ops provides, all bit-identical across implementations:
//   static uint32_t test_node(const WideBvhNode&, const NodeRay&, float t_min, float t_max,
//                             float* entry)  -> mask of children whose box the ray meets in
//                             [t_min, t_max]; entry[i] = where it enters child i
//   static uint32_t test_node_any(const WideBvhNode&, const NodeRay&, float t_min,
//                                 float t_max_far) -> the same mask with the exits widened
//                                 through NodeRay::inv_dir_far (see k_far_scale), no entries
//   static uint32_t sphere_candidates(const float* block, uint32_t count, uint32_t begin,
//                                     const Ray&) -> bit i clear only where sphere begin + i of
//                                     a sphere leaf surely misses (see SphereLeaves)
//   class LeafTest, built once per ray from a LeafRay, with
//     template <bool k_any_hit> bool test(const float* block, uint32_t count, uint32_t first,
//                                         Interval& valid, LeafHit& hit) const
//     -> nearest (or any) triangle of the leaf inside valid; shrinks valid.max and fills hit
//        for the nearest

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "hikari/bvh/sphere_bvh.h"
#include "hikari/bvh/triangle_hit.h"
#include "hikari/bvh/wide_bvh.h"
#include "hikari/core/ray.h"
#include "hikari/geometry/intersect.h"
#include "hikari/geometry/triangle_intersect.h"

namespace hikari::wide_kernel {
// Internal linkage: each kernel translation unit compiles its own copy for its instruction set,
// and the linker must never merge them.
namespace {

/// Bound on the relative rounding error of n float operations (Higham; pbrt's gamma(n)).
constexpr float gamma(int n) {
    constexpr float e = std::numeric_limits<float>::epsilon() * 0.5f;
    return float(n) * e / (1.0f - float(n) * e);
}

/// Ize 2013, "Robust BVH Ray Traversal": widening the exit distance by 1 + 2 gamma(3) makes the
/// slab test conservative, so a box the exact ray touches is never culled.
constexpr float k_exit_scale = 1.0f + 2.0f * gamma(3);

/// The any-hit slab test widens the exit distance before it is computed, by scaling the
/// reciprocal used for the far planes: that side then has four roundings (subtraction, 1 / d,
/// this scaling, product) against the entry side's three, and (1 + gamma(3)) / (1 - gamma(4))
/// < 1 + 2 gamma(4), so the test stays conservative (Ize 2013's argument, one rounding more)
/// with one multiplication less on the per-node critical path.
constexpr float k_far_scale = 1.0f + 2.0f * gamma(4);

/// Per-ray constants of the slab test against a node's SoA boxes.
struct NodeRay {
    std::array<float, 3> origin;
    std::array<float, 3> inv_dir;      ///< 1 / direction; +-inf where a component is +-0
    std::array<float, 3> inv_dir_far;  ///< inv_dir * k_far_scale (any-hit far planes)
    std::array<int, 3> near_row;       ///< row of WideBvhNode::bounds the ray enters by, per axis
    std::array<int, 3> far_row;        ///< row it leaves by

    explicit NodeRay(const Ray& ray) {
        for (int a = 0; a < 3; ++a) {
            origin[a] = ray.origin[a];
            inv_dir[a] = 1.0f / ray.direction[a];
            inv_dir_far[a] = inv_dir[a] * k_far_scale;
            // The sign bit, not `< 0`: 1 / -0 is -inf, and the faces must agree with that sign.
            const int negative = std::signbit(ray.direction[a]) ? 1 : 0;
            near_row[a] = 2 * a + negative;
            far_row[a] = 2 * a + 1 - negative;
        }
    }
};

/// Per-ray constants of the watertight triangle test (WatertightRay's values: the same axis
/// choice and the same divisions), with the axes as indices (rows of a leaf block) and chosen
/// without branches: an incoherent ray's dominant axis is random, and WatertightRay's member
/// pointers cost a mispredicted branch or three per ray (any hit on the bunny: +5%).
struct LeafRay {
    int kx = 0, ky = 1, kz = 2;    ///< axes that become x, y, z in the sheared space
    float sx = 0, sy = 0, sz = 0;  ///< WatertightRay::sx, sy, sz
    float ox = 0, oy = 0, oz = 0;  ///< origin components along kx, ky, kz
    Vec3 origin;

    explicit LeafRay(const Ray& ray) : origin(ray.origin) {
        const std::array<float, 3> d{ray.direction.x, ray.direction.y, ray.direction.z};
        const std::array<float, 3> o{ray.origin.x, ray.origin.y, ray.origin.z};
        const float ax = std::abs(d[0]), ay = std::abs(d[1]), az = std::abs(d[2]);
        // WatertightRay's choice: x if it is at least as long as y and z, else y if at least as
        // long as z, else z; kx and ky follow kz cyclically, swapped where d[kz] < 0. Tables,
        // not `?:`, which g++ compiles to a branch here.
        const int x_wins = int(ax >= ay) & int(ax >= az);
        const int y_wins = int(ay >= az) & (x_wins ^ 1);
        kz = 2 - 2 * x_wins - y_wins;
        static constexpr std::array<int, 6> k_x_axis{1, 2, 0, 2, 0, 1}, k_y_axis{2, 0, 1, 1, 2, 0};
        const int row = kz + 3 * int(d[kz] < 0.0f);
        kx = k_x_axis[row];
        ky = k_y_axis[row];
        sx = d[kx] / d[kz];
        sy = d[ky] / d[kz];
        sz = 1.0f / d[kz];
        ox = o[kx], oy = o[ky], oz = o[kz];
    }

    /// The same constants as a WatertightRay, for the reference test.
    WatertightRay watertight() const {
        constexpr std::array<float Vec3::*, 3> k_axes{&Vec3::x, &Vec3::y, &Vec3::z};
        WatertightRay w;
        w.origin = origin;
        w.kx = k_axes[kx], w.ky = k_axes[ky], w.kz = k_axes[kz];
        w.sx = sx, w.sy = sy, w.sz = sz;
        return w;
    }
};

/// The nearest triangle found so far.
struct LeafHit {
    float t = 0, u = 0, v = 0;
    uint32_t slot = 0;  ///< triangle slot (index into WideBvh::triangle_ids)
};

/// The reference leaf test: one watertight test per triangle, in slot order; the SIMD kernels
/// fall back to it when an edge function is exactly zero (a ray through an edge or vertex).
template <bool k_any_hit>
bool test_leaf_scalar(const LeafRay& ray, const float* block, uint32_t count, uint32_t first,
                      uint32_t begin, uint32_t end, Interval& valid, LeafHit& hit) {
    bool found = false;
    const WatertightRay watertight = ray.watertight();
    for (uint32_t i = begin; i < end; ++i) {
        Vec3 p0, p1, p2;
        load_leaf_triangle(block, count, i, p0, p1, p2);
        if constexpr (k_any_hit) {
            if (triangle_occludes(watertight, p0, p1, p2, valid)) return true;
        } else if (const auto h = intersect_triangle(watertight, p0, p1, p2, valid)) {
            hit = {h->t, h->u, h->v, first + i};
            valid.max = h->t;
            found = true;
        }
    }
    return found;
}

/// A WideBvh's triangle leaves for the closest-hit loop, the triangle test's set-up made at the
/// first leaf: a ray that reaches none (most camera rays beside a model) never pays for it.
template <typename Ops>
class LazyTriangleLeaves {
  public:
    LazyTriangleLeaves(const WideBvh& bvh, const Ray& ray)
        : m_data(bvh.triangle_data.data()), m_ray(ray) {}
    LazyTriangleLeaves(const LazyTriangleLeaves&) = delete;

    template <bool k_any_hit>
    bool test(uint32_t first, uint32_t count, Interval& valid, LeafHit& hit) {
        if (!m_test) m_test.emplace(m_leaf_ray.emplace(m_ray));
        return m_test->template test<k_any_hit>(m_data + 9 * size_t(first), count, first, valid,
                                                hit);
    }
    const void* address(uint32_t first) const { return m_data + 9 * size_t(first); }

  private:
    const float* m_data;
    const Ray& m_ray;
    std::optional<LeafRay> m_leaf_ray;
    std::optional<typename Ops::LeafTest> m_test;
};

/// A WideBvh's triangle leaves for the any-hit loop, the set-up made at once (a shadow ray
/// nearly always reaches a leaf).
template <typename Ops>
class TriangleLeaves {
  public:
    TriangleLeaves(const WideBvh& bvh, const Ray& ray)
        : m_data(bvh.triangle_data.data()), m_leaf_ray(ray), m_test(m_leaf_ray) {}
    TriangleLeaves(const TriangleLeaves&) = delete;

    template <bool k_any_hit>
    bool test(uint32_t first, uint32_t count, Interval& valid, LeafHit& hit) const {
        return m_test.template test<k_any_hit>(m_data + 9 * size_t(first), count, first, valid,
                                               hit);
    }
    const void* address(uint32_t first) const { return m_data + 9 * size_t(first); }

  private:
    const float* m_data;
    const LeafRay m_leaf_ray;
    const typename Ops::LeafTest m_test;
};

/// The next float above `x` (a positive finite distance), without a call into libm.
inline float next_float_up(float x) {
    return x > 0.0f && x < k_infinity ? std::bit_cast<float>(std::bit_cast<uint32_t>(x) + 1)
                                      : std::nextafter(x, k_infinity);
}

/// A SphereBvh's leaves: intersect_sphere for each sphere, in slot order, so every SIMD level
/// and every caller gets its exact t; Ops::sphere_candidates first drops, eight at a time, the
/// spheres whose discriminant is negative (most of a leaf's). Of spheres at exactly the same
/// distance the one of lowest index wins, as when all are tested in index order, each needing
/// to be strictly nearer.
template <typename Ops>
class SphereLeaves {
  public:
    SphereLeaves(const SphereBvh& bvh, const Ray& ray)
        : m_data(bvh.sphere_data.data()), m_ids(bvh.tree.triangle_ids.data()), m_ray(ray) {}
    SphereLeaves(const SphereLeaves&) = delete;

    template <bool k_any_hit>
    bool test(uint32_t first, uint32_t count, Interval& valid, LeafHit& hit) {
        bool found = false;
        const float* block = m_data + 4 * size_t(first);
        for (uint32_t begin = 0; begin < count; begin += k_wide_bvh_width) {
            // (No std::min: a library template instantiated under a kernel's target pragma could
            // be the copy the linker keeps for baseline code.)
            const uint32_t left = count - begin;
            const uint32_t lanes = left < k_wide_bvh_width ? left : k_wide_bvh_width;
            uint32_t mask =
                Ops::sphere_candidates(block, count, begin, m_ray) & ((1u << lanes) - 1u);
            for (; mask != 0; mask &= mask - 1) {
                const uint32_t i = begin + static_cast<uint32_t>(std::countr_zero(mask));
                const uint32_t slot = first + i;
                const Vec3 center{block[i], block[count + i], block[2 * count + i]};
                // Once a sphere holds valid.max, a sphere of lower index at that t wins too.
                const Interval range{valid.min, m_found ? next_float_up(valid.max) : valid.max};
                const float t = intersect_sphere(m_ray, center, block[3 * count + i], range);
                if (!(t == t)) continue;  // NaN: no hit
                if constexpr (k_any_hit) return true;
                if (t == valid.max && m_ids[slot] > m_best_id) continue;
                valid.max = t;
                hit.t = t, hit.slot = slot;
                m_best_id = m_ids[slot];
                m_found = found = true;
            }
        }
        return found;
    }
    const void* address(uint32_t first) const { return m_data + 4 * size_t(first); }

  private:
    const float* m_data;
    const uint32_t* m_ids;
    const Ray& m_ray;
    bool m_found = false;  ///< a sphere holds valid.max
    uint32_t m_best_id = 0;
};

/// Rays the traversal can handle: finite origin, finite non-zero direction.
inline bool is_traceable(const Ray& ray) {
    return is_finite(ray.origin) && is_finite(ray.direction) && !(ray.direction == Vec3(0.0f));
}

/// A child deferred by the closest-hit loop.
struct StackEntry {
    uint32_t ref;
    float entry;  ///< where the ray enters it: skip it once a hit is nearer
};

/// The closest-hit loop: a stack of (reference, entry distance); at an inner node all eight
/// boxes are tested at once and the hit children visited nearest first.
template <typename Ops, typename Leaves>
bool traverse(const WideBvh& bvh, const Ray& ray, Interval valid, Leaves& leaves, LeafHit& hit) {
    if (bvh.empty() || !is_traceable(ray)) return false;
    const NodeRay node_ray(ray);
    const WideBvhNode* nodes = bvh.nodes.data();

    std::array<StackEntry, k_wide_bvh_stack_size> stack;
    uint32_t stack_size = 0;
    alignas(32) std::array<float, k_wide_bvh_width> entry;

    uint32_t current = bvh.root;
    bool found = false;
    for (;;) {
        if (!WideBvhRef::is_leaf(current)) {
            /* inner node: test eight boxes, go to the nearest hit child, defer the others */
            const WideBvhNode& node = nodes[current];
            uint32_t mask = Ops::test_node(node, node_ray, valid.min, valid.max, entry.data());
            if (mask != 0) {
                uint32_t first = static_cast<uint32_t>(std::countr_zero(mask));
                mask &= mask - 1;
                if (mask == 0) {
                    current = node.child[first];
                    continue;
                }
                // Insertion sort by entry distance (ties keep slot order), then push
                // farthest first so the nearest is popped first.
                std::array<StackEntry, k_wide_bvh_width> hits;
                uint32_t n = 0;
                hits[n++] = {node.child[first], entry[first]};
                for (; mask != 0; mask &= mask - 1) {
                    const auto i = static_cast<uint32_t>(std::countr_zero(mask));
                    const StackEntry e{node.child[i], entry[i]};
                    uint32_t k = n++;
                    for (; k > 0 && hits[k - 1].entry > e.entry; --k) hits[k] = hits[k - 1];
                    hits[k] = e;
                }
                for (uint32_t k = n - 1; k > 0; --k) stack[stack_size++] = hits[k];
                current = hits[0].ref;
                continue;
            }
        } else {
            /* leaf: test its primitives; a nearest hit shrinks valid.max */
            const uint32_t first = WideBvhRef::leaf_first(current);
            const uint32_t count = WideBvhRef::leaf_count(current);
            if (leaves.template test<false>(first, count, valid, hit)) found = true;
        }

        /* pop the next node that starts before the nearest hit so far */
        bool popped = false;
        const float limit = valid.max * k_exit_scale;
        while (stack_size > 0 && !popped) {
            const StackEntry next = stack[--stack_size];
            popped = next.entry <= limit;
            current = next.ref;
        }
        if (!popped) return found;
    }
}

/// The closest-hit loop over a triangle tree.
template <typename Ops>
bool traverse(const WideBvh& bvh, const Ray& ray, Interval valid, LeafHit& hit) {
    LazyTriangleLeaves<Ops> leaves(bvh, ray);
    return traverse<Ops>(bvh, ray, valid, leaves, hit);
}

/// Starts loading the first four cache lines of a child pushed for later: an inner node (224
/// bytes) or a leaf's triangle rows (up to 7 triangles), so that its misses overlap the walk of
/// the siblings before it, as Embree's traversal does for the children it pushes. Measured on
/// the any-hit walk (both walks alternated in one process over all B2 rays): +1 to +6% on
/// bumpy1m, level to +7% on the bunny; 3-10% in separate processes in the VM's slow phases.
template <typename Leaves>
inline void prefetch_child(const WideBvhNode* nodes, const Leaves& leaves, uint32_t ref) {
    const char* line = WideBvhRef::is_leaf(ref)
                           ? static_cast<const char*>(leaves.address(WideBvhRef::leaf_first(ref)))
                           : reinterpret_cast<const char*>(nodes + ref);
    for (int k = 0; k < 4; ++k) __builtin_prefetch(line + 64 * k);
}

/// The any-hit loop (shadow rays): children in slot order, a stack of bare references. A
/// hit ends the walk, so valid.max never shrinks, and every pushed child (entered before
/// valid.max) stays worth visiting: no entry distances, no test when popping.
template <typename Ops, typename Leaves>
bool occluded(const WideBvh& bvh, const Ray& ray, Interval valid, Leaves& leaves) {
    if (bvh.empty() || !is_traceable(ray)) return false;
    const NodeRay node_ray(ray);
    const WideBvhNode* nodes = bvh.nodes.data();

    std::array<uint32_t, k_wide_bvh_stack_size> stack;
    uint32_t stack_size = 0;
    LeafHit unused;

    const float t_max_far = valid.max * k_far_scale;
    uint32_t current = bvh.root;
    for (;;) {
        if (!WideBvhRef::is_leaf(current)) {
            /* inner node: go to the first hit child, defer the others */
            const WideBvhNode& node = nodes[current];
            uint32_t mask = Ops::test_node_any(node, node_ray, valid.min, t_max_far);
            if (mask != 0) {
                current = node.child[std::countr_zero(mask)];
                for (mask &= mask - 1; mask != 0; mask &= mask - 1) {
                    const uint32_t deferred = node.child[std::countr_zero(mask)];
                    stack[stack_size++] = deferred;
                    prefetch_child(nodes, leaves, deferred);
                }
                continue;
            }
        } else {
            /* leaf: any primitive inside valid ends the walk */
            const uint32_t first = WideBvhRef::leaf_first(current);
            const uint32_t count = WideBvhRef::leaf_count(current);
            if (leaves.template test<true>(first, count, valid, unused)) return true;
        }

        /* pop the next node */
        if (stack_size == 0) return false;
        current = stack[--stack_size];
    }
}

/// The any-hit loop over a triangle tree.
template <typename Ops>
bool occluded(const WideBvh& bvh, const Ray& ray, Interval valid) {
    if (bvh.empty() || !is_traceable(ray)) return false;
    TriangleLeaves<Ops> leaves(bvh, ray);
    return occluded<Ops>(bvh, ray, valid, leaves);
}

/// The nearest sphere of `bvh` along `ray` inside `valid`.
template <typename Ops>
bool closest_sphere(const SphereBvh& bvh, const Ray& ray, Interval valid, SphereHit& hit) {
    SphereLeaves<Ops> leaves(bvh, ray);
    LeafHit h;
    if (!traverse<Ops>(bvh.tree, ray, valid, leaves, h)) return false;
    hit = {h.t, bvh.tree.triangle_ids[h.slot]};
    return true;
}

/// Whether any sphere of `bvh` meets `ray` inside `valid`.
template <typename Ops>
bool any_sphere(const SphereBvh& bvh, const Ray& ray, Interval valid) {
    SphereLeaves<Ops> leaves(bvh, ray);
    return occluded<Ops>(bvh.tree, ray, valid, leaves);
}

/// The hit as the public API reports it.
inline TriangleHit to_triangle_hit(const WideBvh& bvh, const LeafHit& h) {
    return {h.t, h.u, h.v, bvh.triangle_ids[h.slot]};
}

}  // namespace
}  // namespace hikari::wide_kernel
