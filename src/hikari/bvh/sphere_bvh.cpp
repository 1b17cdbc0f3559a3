#include "hikari/bvh/sphere_bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "hikari/bvh/wide_bvh_builder.h"
#include "hikari/core/memory_budget.h"
#include "hikari/core/parallel.h"

namespace hikari {
namespace {

/// The sphere's box, grown by a few units in the last place of its coordinates: the box test is
/// conservative for the exact ray (Ize 2013), but intersect_sphere's rounded t may fall a few
/// ulps outside the exact box, and such a hit must not be culled.
Aabb padded_box(const Sphere& s) {
    const float magnitude =
        std::max({std::abs(s.center.x), std::abs(s.center.y), std::abs(s.center.z)}) + s.radius;
    const float reach = s.radius + 8.0f * std::numeric_limits<float>::epsilon() * magnitude;
    return {s.center - Vec3(reach), s.center + Vec3(reach)};
}

}  // namespace

SphereBvh build_sphere_bvh(std::span<const Sphere> spheres, bool casters_only) {
    check_memory_need(double(spheres.size()) * sizeof(Aabb),
                      fmt::format("the boxes of {} spheres", spheres.size()));
    std::vector<Aabb> boxes(spheres.size());
    parallel_for(size_t(0), spheres.size(), [&](size_t i) {
        const Sphere& s = spheres[i];
        // An empty box leaves the sphere out of the tree.
        const bool usable = (!casters_only || s.casts_shadow) && is_finite(s.center) &&
                            std::isfinite(s.radius) && s.radius >= 0.0f;
        boxes[i] = usable ? padded_box(s) : Aabb{};
    });
    SphereBvh bvh;
    bvh.tree = build_wide_bvh_over_boxes(boxes);
    const size_t n = bvh.sphere_count();
    if (n == 0) return bvh;
    check_memory_need(double(n) * 4 * sizeof(float), fmt::format("the BVH of {} spheres", n));
    bvh.sphere_data.resize(4 * n + k_wide_bvh_width);
    // Every leaf is a child of one node (or the root): fill each leaf's rows from there.
    const auto write_leaf = [&](uint32_t ref) {
        if (ref == WideBvhRef::k_empty || !WideBvhRef::is_leaf(ref)) return;
        const uint32_t first = WideBvhRef::leaf_first(ref), count = WideBvhRef::leaf_count(ref);
        float* block = bvh.sphere_data.data() + 4 * size_t(first);
        for (uint32_t i = 0; i < count; ++i) {
            const Sphere& s = spheres[bvh.tree.triangle_ids[first + i]];
            block[i] = s.center.x, block[count + i] = s.center.y;
            block[2 * count + i] = s.center.z, block[3 * count + i] = s.radius;
        }
    };
    write_leaf(bvh.tree.root);
    parallel_for(size_t(0), bvh.tree.nodes.size(), [&](size_t k) {
        for (uint32_t ref : bvh.tree.nodes[k].child) write_leaf(ref);
    });
    return bvh;
}

}  // namespace hikari
