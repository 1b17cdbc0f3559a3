#include "hikari/ray/wide_bvh_builder.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "test_meshes.h"

namespace hikari {
namespace {

using testing::TestMesh;

/// Box of child slot i of a wide node.
Aabb child_box(const WideBvhNode& node, uint32_t i) {
    return {{node.bounds[0][i], node.bounds[2][i], node.bounds[4][i]},
            {node.bounds[1][i], node.bounds[3][i], node.bounds[5][i]}};
}

/// Walks the wide tree: every triangle slot in exactly one leaf, inside its leaf's box, and
/// stored as the mesh's own vertices.
void check_ref(const WideBvh& bvh, const TestMesh& mesh, uint32_t ref, const Aabb& box,
               std::vector<int>& uses) {
    if (WideBvhRef::is_leaf(ref)) {
        const uint32_t first = WideBvhRef::leaf_first(ref), count = WideBvhRef::leaf_count(ref);
        const float* block = bvh.triangle_data.data() + 9 * size_t(first);
        for (uint32_t i = 0; i < count; ++i) {
            ++uses.at(first + i);
            const auto& tri = mesh.indices[bvh.triangle_ids[first + i]];
            for (int v = 0; v < 3; ++v) {
                for (int a = 0; a < 3; ++a)
                    ASSERT_EQ(block[(3 * v + a) * count + i], mesh.positions[tri[v]][a]);
                EXPECT_TRUE(box.contains(Aabb::from_point(mesh.positions[tri[v]])));
            }
        }
        return;
    }
    const WideBvhNode& node = bvh.nodes.at(ref);
    int used = 0;
    for (uint32_t i = 0; i < k_wide_bvh_width; ++i) {
        if (node.child[i] == WideBvhRef::k_empty) {
            EXPECT_GT(node.bounds[0][i], node.bounds[1][i]);  // the empty box
            continue;
        }
        ++used;
        EXPECT_TRUE(box.contains(child_box(node, i)));
        check_ref(bvh, mesh, node.child[i], child_box(node, i), uses);
    }
    EXPECT_GE(used, 2);
}

void check_tree(const WideBvh& bvh, const TestMesh& mesh) {
    ASSERT_FALSE(bvh.empty());
    ASSERT_EQ(bvh.triangle_count(), mesh.indices.size());
    std::vector<int> uses(mesh.indices.size(), 0);
    check_ref(bvh, mesh, bvh.root, bvh.root_bounds, uses);
    EXPECT_TRUE(std::all_of(uses.begin(), uses.end(), [](int u) { return u == 1; }));
}

TEST(WideBvhBuilder, EmptyInputGivesEmptyTree) { EXPECT_TRUE(build_wide_bvh({}, {}).empty()); }

TEST(WideBvhBuilder, SingleLeafBecomesRoot) {
    const TestMesh mesh = testing::random_soup(1, 0.5f, 4);
    const WideBvh bvh = build_wide_bvh(mesh.positions, mesh.indices);
    EXPECT_TRUE(WideBvhRef::is_leaf(bvh.root));
    check_tree(bvh, mesh);
}

TEST(WideBvhBuilder, SphereAndSoupKeepInvariants) {
    check_tree(build_wide_bvh(testing::uv_sphere(64, 32, 1.0f).positions,
                              testing::uv_sphere(64, 32, 1.0f).indices),
               testing::uv_sphere(64, 32, 1.0f));
    const TestMesh soup = testing::random_soup(5000, 0.2f, 5);
    check_tree(build_wide_bvh(soup.positions, soup.indices), soup);
}

TEST(WideBvhBuilder, NodesHoldSeveralChildren) {
    const TestMesh mesh = testing::random_soup(20000, 0.05f, 6);
    const WideBvh bvh = build_wide_bvh(mesh.positions, mesh.indices);
    size_t used = 0;
    for (const WideBvhNode& node : bvh.nodes)
        for (uint32_t c : node.child) used += c != WideBvhRef::k_empty;
    EXPECT_GT(double(used) / double(bvh.nodes.size()), 3.0);
}

TEST(WideBvhBuilder, MemoryWithinSixtyFourBytesPerTriangle) {
    const TestMesh mesh = testing::uv_sphere(256, 128, 1.0f);
    const WideBvh bvh = build_wide_bvh(mesh.positions, mesh.indices);
    EXPECT_LE(bvh.memory_bytes(), 64 * mesh.indices.size());
}

TEST(WideBvhBuilder, IdenticalForAnyThreadCount) {
    const TestMesh mesh = testing::random_soup(20000, 0.1f, 9);
    BvhBuildSettings settings;
    settings.parallel_threshold = 64;
    const auto build_with = [&](int threads) {
        return tbb::task_arena(threads).execute(
            [&] { return build_wide_bvh(mesh.positions, mesh.indices, settings); });
    };
    const WideBvh one = build_with(1);
    const WideBvh two = build_with(2);
    ASSERT_EQ(one.nodes.size(), two.nodes.size());
    EXPECT_EQ(
        std::memcmp(one.nodes.data(), two.nodes.data(), one.nodes.size() * sizeof(WideBvhNode)), 0);
    EXPECT_EQ(one.triangle_ids, two.triangle_ids);
    EXPECT_EQ(one.triangle_data, two.triangle_data);
    EXPECT_EQ(one.root, two.root);
}

}  // namespace
}  // namespace hikari
