#include "hikari/ray/wide_bvh_builder.h"

#include <stdexcept>
#include <vector>

namespace hikari {
namespace {

/// Collapses the binary subtree under each inner node into one wide node, depth first.
class Collapser {
  public:
    Collapser(const Bvh& binary, WideBvh& wide) : m_binary(binary), m_wide(wide) {}

    /// The reference for binary node `b`, creating the wide nodes below it.
    uint32_t collapse(uint32_t b) {
        const BvhNode& node = m_binary.nodes[b];
        if (node.is_leaf()) return leaf_ref(node);
        const auto slot = static_cast<uint32_t>(m_wide.nodes.size());
        m_wide.nodes.emplace_back();
        const std::vector<uint32_t> children = open_children(node);
        WideBvhNode wide{};
        for (auto& row : wide.bounds) row.fill(0.0f);
        for (int a = 0; a < 3; ++a) {
            wide.bounds[2 * a].fill(k_infinity);
            wide.bounds[2 * a + 1].fill(-k_infinity);
        }
        wide.child.fill(WideBvhRef::k_empty);
        for (size_t i = 0; i < children.size(); ++i) {
            const Aabb& box = m_binary.nodes[children[i]].bounds;
            for (int a = 0; a < 3; ++a) {
                wide.bounds[2 * a][i] = box.min[a];
                wide.bounds[2 * a + 1][i] = box.max[a];
            }
            wide.child[i] = collapse(children[i]);
        }
        m_wide.nodes[slot] = wide;
        return WideBvhRef::inner(slot);
    }

  private:
    static uint32_t leaf_ref(const BvhNode& leaf) {
        if (leaf.triangle_count > WideBvhRef::k_max_leaf_size)
            throw std::invalid_argument("wide BVH: leaves hold at most 16 triangles");
        return WideBvhRef::leaf(leaf.index, leaf.triangle_count);
    }

    /// Wald et al. 2008: pull grandchildren up, always opening the inner child with the largest
    /// surface area (the one most rays would enter), until eight children or only leaves.
    std::vector<uint32_t> open_children(const BvhNode& node) const {
        std::vector<uint32_t> children = {node.index, node.index + 1};
        while (children.size() < k_wide_bvh_width) {
            int best = -1;
            float best_area = -1.0f;
            for (size_t i = 0; i < children.size(); ++i) {
                const BvhNode& c = m_binary.nodes[children[i]];
                if (!c.is_leaf() && c.bounds.half_area() > best_area) {
                    best = static_cast<int>(i);
                    best_area = c.bounds.half_area();
                }
            }
            if (best < 0) break;
            const uint32_t first = m_binary.nodes[children[best]].index;
            children[best] = first;
            children.insert(children.begin() + best + 1, first + 1);
        }
        return children;
    }

    const Bvh& m_binary;
    WideBvh& m_wide;
};

/// Writes each leaf's triangles as nine rows of `count` floats at 9 * first.
void write_triangle_data(const Bvh& binary, HugePageVector<float>& data) {
    data.assign(9 * binary.triangles.size() + k_wide_bvh_width, 0.0f);
    for (const BvhNode& node : binary.nodes) {
        if (!node.is_leaf()) continue;
        const uint32_t first = node.index, count = node.triangle_count;
        float* block = data.data() + 9 * size_t(first);
        for (uint32_t i = 0; i < count; ++i) {
            const BvhTriangle& tri = binary.triangles[first + i];
            const Vec3 p[3] = {tri.p0, tri.p1, tri.p2};
            for (int v = 0; v < 3; ++v)
                for (int a = 0; a < 3; ++a) block[(3 * v + a) * count + i] = p[v][a];
        }
    }
}

}  // namespace

WideBvh collapse_to_wide_bvh(const Bvh& binary) {
    WideBvh wide;
    if (binary.empty()) return wide;
    if (binary.triangles.size() >= WideBvhRef::k_max_triangles)
        throw std::invalid_argument("wide BVH: too many triangles");
    wide.nodes.reserve(binary.nodes.size() / 4 + 1);
    wide.root = Collapser(binary, wide).collapse(0);
    wide.root_bounds = binary.bounds();
    wide.nodes.shrink_to_fit();
    write_triangle_data(binary, wide.triangle_data);
    wide.triangle_ids.assign(binary.triangle_ids.begin(), binary.triangle_ids.end());
    return wide;
}

WideBvh build_wide_bvh(std::span<const Vec3> positions,
                       std::span<const std::array<uint32_t, 3>> indices,
                       const BvhBuildSettings& settings) {
    return collapse_to_wide_bvh(build_bvh(positions, indices, settings));
}

}  // namespace hikari
