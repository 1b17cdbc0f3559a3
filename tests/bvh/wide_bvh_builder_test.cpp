#include "hikari/bvh/wide_bvh_builder.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "hikari/bvh/wide_bvh_traversal.h"
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
/// stored as the mesh's own vertices; no path deeper than the traversal stacks allow.
void check_ref(const WideBvh& bvh, const TestMesh& mesh, uint32_t ref, const Aabb& box,
               uint32_t depth, std::vector<int>& uses) {
    ASSERT_LT(depth, k_bvh_max_depth);
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
        check_ref(bvh, mesh, node.child[i], child_box(node, i), depth + 1, uses);
    }
    EXPECT_GE(used, 2);
}

void check_tree(const WideBvh& bvh, const TestMesh& mesh) {
    ASSERT_FALSE(bvh.empty());
    ASSERT_EQ(bvh.triangle_count(), mesh.indices.size());
    std::vector<int> uses(mesh.indices.size(), 0);
    check_ref(bvh, mesh, bvh.root, bvh.root_bounds, 0, uses);
    EXPECT_TRUE(std::all_of(uses.begin(), uses.end(), [](int u) { return u == 1; }));
}

TEST(WideBvhBuilder, EmptyInputGivesEmptyTree) {
    const WideBvh bvh = build_wide_bvh({}, {});
    EXPECT_TRUE(bvh.empty());
    EXPECT_EQ(bvh.triangle_count(), 0u);
    EXPECT_EQ(bvh.memory_bytes(), 0u);
}

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

/// Largest leaf of the tree under `ref`.
uint32_t largest_leaf(const WideBvh& bvh, uint32_t ref) {
    if (WideBvhRef::is_leaf(ref)) return WideBvhRef::leaf_count(ref);
    uint32_t largest = 0;
    for (uint32_t c : bvh.nodes.at(ref).child)
        if (c != WideBvhRef::k_empty) largest = std::max(largest, largest_leaf(bvh, c));
    return largest;
}

TEST(WideBvhBuilder, LeavesOutUnusableTriangles) {
    const float nan = std::nanf("");
    TestMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {nan, 0, 0}, {0, 0, 1}};
    mesh.indices = {{0, 1, 3}, {0, 1, 2}, {0, 1, 4}, {0, 1, 9}, {2, 2, 2}, {0, 2, 5}};
    const WideBvh bvh = build_wide_bvh(mesh.positions, mesh.indices);
    std::vector<uint32_t> ids(bvh.triangle_ids.begin(), bvh.triangle_ids.end());
    std::sort(ids.begin(), ids.end());
    EXPECT_EQ(ids, (std::vector<uint32_t>{1, 5}));

    mesh.indices = {{0, 1, 3}, {0, 1, 4}};
    EXPECT_TRUE(build_wide_bvh(mesh.positions, mesh.indices).empty());
}

TEST(WideBvhBuilder, CoincidentTrianglesStillSplit) {
    // All centroids equal: no SAH plane separates them, so the builder halves by index.
    TestMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.indices.assign(1000, {0, 1, 2});
    const WideBvh bvh = build_wide_bvh(mesh.positions, mesh.indices);
    check_tree(bvh, mesh);
    EXPECT_LE(largest_leaf(bvh, bvh.root), 8u);
}

TEST(WideBvhBuilder, ExtremeCoordinatesBuild) {
    // Centroids a denormal apart (bin scale K / extent overflows), a huge mesh (areas overflow)
    // and one near the float limit (doubled centroids overflow): all must give valid trees.
    TestMesh tiny;
    for (uint32_t i = 0; i < 100; ++i) {
        const float dx = float(i) * 1e-40f;
        const auto base = static_cast<uint32_t>(tiny.positions.size());
        tiny.positions.insert(tiny.positions.end(), {{dx, 0, 0}, {1 + dx, 0, 0}, {dx, 1, 0}});
        tiny.indices.push_back({base, base + 1, base + 2});
    }
    check_tree(build_wide_bvh(tiny.positions, tiny.indices), tiny);
    for (const float scale : {1e37f, 2.5e38f}) {
        TestMesh huge = testing::random_soup(500, 0.5f, 13);
        for (Vec3& p : huge.positions) p = p * scale;
        check_tree(build_wide_bvh(huge.positions, huge.indices), huge);
    }
}

TEST(WideBvhBuilder, LeavesRespectMaxLeafSize) {
    const TestMesh mesh = testing::random_soup(2000, 0.2f, 5);
    BvhBuildSettings settings;
    settings.max_leaf_size = 1;  // also more nodes than the first node block holds
    const WideBvh small = build_wide_bvh(mesh.positions, mesh.indices, settings);
    check_tree(small, mesh);
    EXPECT_LE(largest_leaf(small, small.root), 1u);
    EXPECT_GT(small.nodes.size(), 256u);
    settings.max_leaf_size = 200;  // clamped to what a WideBvhRef can hold
    const WideBvh big = build_wide_bvh(mesh.positions, mesh.indices, settings);
    check_tree(big, mesh);
    EXPECT_LE(largest_leaf(big, big.root), WideBvhRef::k_max_leaf_size);
}

TEST(WideBvhBuilder, ParallelPathsGiveCorrectTree) {
    // A tiny threshold sends most ranges through the task, parallel binning and parallel
    // partition paths, on several threads.
    const TestMesh mesh = testing::random_soup(10000, 0.05f, 17);
    BvhBuildSettings settings;
    settings.parallel_threshold = 32;
    const WideBvh bvh = tbb::task_arena(2).execute(
        [&] { return build_wide_bvh(mesh.positions, mesh.indices, settings); });
    check_tree(bvh, mesh);
    Pcg32 rng(18, 1);
    for (int i = 0; i < 200; ++i) {
        const Ray ray{testing::random_point(rng, 1.5f), testing::random_direction(rng)};
        const auto expected = testing::brute_force_closest(mesh, ray, {});
        TriangleHit hit;
        ASSERT_EQ(intersect_closest(bvh, ray, {}, hit, SimdLevel::portable), expected.has_value());
        if (expected) EXPECT_EQ(hit.t, expected->hit.t);
    }
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
