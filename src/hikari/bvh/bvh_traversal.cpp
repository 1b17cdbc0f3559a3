#include "hikari/bvh/bvh_traversal.h"

#include <array>
#include <limits>

#include "hikari/geometry/triangle_intersect.h"

namespace hikari {
namespace {

/// Bound on the relative rounding error of n float operations (Higham; pbrt's gamma(n)).
constexpr float gamma(int n) {
    constexpr float e = std::numeric_limits<float>::epsilon() * 0.5f;
    return float(n) * e / (1.0f - float(n) * e);
}

/// Ize 2013, "Robust BVH Ray Traversal" (JCGT 2(2)): the slab distances (b - o) * (1 / d) are
/// each off by at most 3 roundings; widening the exit distance by 1 + 2 gamma(3) makes the test
/// conservative, so a box the exact ray touches is never culled.
constexpr float k_exit_scale = 1.0f + 2.0f * gamma(3);

/// The per-ray constants of the slab test: the inverse direction and, per axis, which face of
/// a box the ray meets first (the near face is max when the direction is negative).
struct SlabRay {
    Vec3 origin;
    Vec3 inv_dir;  ///< 1 / direction; +-inf where a component is +-0
    Vec3 Aabb::*near_x;
    Vec3 Aabb::*near_y;
    Vec3 Aabb::*near_z;
    Vec3 Aabb::*far_x;
    Vec3 Aabb::*far_y;
    Vec3 Aabb::*far_z;
    std::array<uint32_t, 3> negative;  ///< 1 where the direction points to -axis, else 0

    explicit SlabRay(const Ray& ray) : origin(ray.origin) {
        const Vec3 d = ray.direction;
        inv_dir = {1.0f / d.x, 1.0f / d.y, 1.0f / d.z};
        // The sign bit, not `< 0`: 1 / -0 is -inf, and the faces must agree with that sign.
        negative = {std::signbit(d.x) ? 1u : 0u, std::signbit(d.y) ? 1u : 0u,
                    std::signbit(d.z) ? 1u : 0u};
        near_x = negative[0] ? &Aabb::max : &Aabb::min;
        near_y = negative[1] ? &Aabb::max : &Aabb::min;
        near_z = negative[2] ? &Aabb::max : &Aabb::min;
        far_x = negative[0] ? &Aabb::min : &Aabb::max;
        far_y = negative[1] ? &Aabb::min : &Aabb::max;
        far_z = negative[2] ? &Aabb::min : &Aabb::max;
    }
};

/// Kay & Kajiya slab test of `box` against the ray within [valid.min, valid.max]. On a hit,
/// `entry` is where the ray enters the box (or valid.min when it starts inside).
inline bool hit_box(const Aabb& box, const SlabRay& ray, Interval valid, float& entry) {
    const float near_x = ((box.*ray.near_x).x - ray.origin.x) * ray.inv_dir.x;
    const float near_y = ((box.*ray.near_y).y - ray.origin.y) * ray.inv_dir.y;
    const float near_z = ((box.*ray.near_z).z - ray.origin.z) * ray.inv_dir.z;
    const float far_x = ((box.*ray.far_x).x - ray.origin.x) * ray.inv_dir.x;
    const float far_y = ((box.*ray.far_y).y - ray.origin.y) * ray.inv_dir.y;
    const float far_z = ((box.*ray.far_z).z - ray.origin.z) * ray.inv_dir.z;
    // A ray lying in a face plane gives 0 * inf = NaN; every comparison below is written so a
    // NaN loses, which leaves that slab unbounded (conservative).
    float t0 = valid.min;
    float t1 = valid.max;
    t0 = near_x > t0 ? near_x : t0;
    t0 = near_y > t0 ? near_y : t0;
    t0 = near_z > t0 ? near_z : t0;
    t1 = far_x < t1 ? far_x : t1;
    t1 = far_y < t1 ? far_y : t1;
    t1 = far_z < t1 ? far_z : t1;
    entry = t0;
    return t0 <= t1 * k_exit_scale;
}

/// Rays the traversal can handle: finite origin, finite non-zero direction.
bool is_traceable(const Ray& ray) {
    return is_finite(ray.origin) && is_finite(ray.direction) && !(ray.direction == Vec3(0.0f));
}

/// The traversal loop, written once: stack-based, children tested in pairs and visited nearer
/// side first by the sign of the direction along the node's split axis. `leaf_test(node,
/// valid)` tests a leaf's triangles, shrinks valid.max to a hit it finds and returns whether it
/// found one. With k_any_hit the loop stops at the first hit.
template <bool k_any_hit, typename LeafTest>
bool traverse(const Bvh& bvh, const Ray& ray, Interval valid, LeafTest&& leaf_test) {
    if (bvh.empty() || !is_traceable(ray)) return false;
    const SlabRay slab(ray);
    const BvhNode* nodes = bvh.nodes.data();

    struct StackEntry {
        uint32_t node;
        float entry;  ///< where the ray enters the node: skip it once a hit is nearer
    };
    std::array<StackEntry, k_bvh_max_depth> stack;
    uint32_t stack_size = 0;

    float root_entry = 0;
    if (!hit_box(nodes[0].bounds, slab, valid, root_entry)) return false;
    uint32_t current = 0;
    bool found = false;
    for (;;) {
        const BvhNode& node = nodes[current];
        if (!node.is_leaf()) {
            /* inner node: test both children, go to the nearer, defer the farther */
            const uint32_t first = node.index;
            float entry0 = 0, entry1 = 0;
            const bool hit0 = hit_box(nodes[first].bounds, slab, valid, entry0);
            const bool hit1 = hit_box(nodes[first + 1].bounds, slab, valid, entry1);
            if (hit0 && hit1) {
                const uint32_t near = slab.negative[node.split_axis];
                stack[stack_size++] =
                    near ? StackEntry{first, entry0} : StackEntry{first + 1, entry1};
                current = first + near;
                continue;
            }
            if (hit0 || hit1) {
                current = hit0 ? first : first + 1;
                continue;
            }
        } else if (leaf_test(node, valid)) {
            /* leaf: a hit shrank valid.max */
            if constexpr (k_any_hit) return true;
            found = true;
        }

        /* pop the next node that starts before the nearest hit so far */
        bool popped = false;
        while (stack_size > 0 && !popped) {
            const StackEntry next = stack[--stack_size];
            popped = next.entry <= valid.max * k_exit_scale;
            current = next.node;
        }
        if (!popped) return found;
    }
}

}  // namespace

bool intersect_closest(const Bvh& bvh, const Ray& ray, Interval valid, TriangleHit& hit) {
    const WatertightRay shear(ray);
    const BvhTriangle* triangles = bvh.triangles.data();
    TriangleIntersection nearest;
    uint32_t nearest_slot = 0;
    const auto leaf_test = [&](const BvhNode& leaf, Interval& range) {
        bool found = false;
        for (uint32_t i = leaf.index, end = leaf.index + leaf.triangle_count; i < end; ++i) {
            const BvhTriangle& tri = triangles[i];
            if (const auto h = intersect_triangle(shear, tri.p0, tri.p1, tri.p2, range)) {
                nearest = *h;
                nearest_slot = i;
                range.max = h->t;
                found = true;
            }
        }
        return found;
    };
    if (!traverse<false>(bvh, ray, valid, leaf_test)) return false;
    hit = {nearest.t, nearest.u, nearest.v, bvh.triangle_ids[nearest_slot]};
    return true;
}

bool intersect_any(const Bvh& bvh, const Ray& ray, Interval valid) {
    const WatertightRay shear(ray);
    const BvhTriangle* triangles = bvh.triangles.data();
    const auto leaf_test = [&](const BvhNode& leaf, Interval range) {
        for (uint32_t i = leaf.index, end = leaf.index + leaf.triangle_count; i < end; ++i) {
            const BvhTriangle& tri = triangles[i];
            if (triangle_occludes(shear, tri.p0, tri.p1, tri.p2, range)) return true;
        }
        return false;
    };
    return traverse<true>(bvh, ray, valid, leaf_test);
}

}  // namespace hikari
