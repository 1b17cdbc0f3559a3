#include "hikari/bvh/bvh_builder.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "test_meshes.h"

namespace hikari {
namespace {

using testing::TestMesh;

Bvh build(const TestMesh& mesh, const BvhBuildSettings& settings = {}) {
    return build_bvh(mesh.positions, mesh.indices, settings);
}

/// Walks the tree, checking the structural invariants, and returns its depth.
uint32_t check_subtree(const Bvh& bvh, uint32_t index, uint32_t depth, std::vector<int>& uses) {
    const BvhNode& node = bvh.nodes[index];
    EXPECT_EQ(node.reserved, 0);
    if (node.is_leaf()) {
        for (uint32_t i = node.index; i < node.index + node.triangle_count; ++i) {
            ++uses.at(i);
            const BvhTriangle& tri = bvh.triangles[i];
            Aabb box;
            for (Vec3 p : {tri.p0, tri.p1, tri.p2}) box.extend(p);
            EXPECT_TRUE(node.bounds.contains(box)) << "leaf " << index << " triangle " << i;
        }
        return depth;
    }
    EXPECT_LT(node.index + 1, bvh.nodes.size());
    EXPECT_LE(node.split_axis, 2);
    uint32_t deepest = depth;
    for (uint32_t c = node.index; c <= node.index + 1; ++c) {
        EXPECT_TRUE(node.bounds.contains(bvh.nodes[c].bounds)) << "child " << c;
        deepest = std::max(deepest, check_subtree(bvh, c, depth + 1, uses));
    }
    return deepest;
}

/// Every invariant of a built tree over `mesh`, all of whose triangles are usable.
void check_tree(const Bvh& bvh, const TestMesh& mesh) {
    ASSERT_FALSE(bvh.empty());
    ASSERT_EQ(bvh.triangles.size(), mesh.indices.size());
    ASSERT_EQ(bvh.triangle_ids.size(), mesh.indices.size());
    std::vector<int> uses(bvh.triangles.size(), 0);
    EXPECT_LT(check_subtree(bvh, 0, 0, uses), k_bvh_max_depth);
    EXPECT_TRUE(std::all_of(uses.begin(), uses.end(), [](int u) { return u == 1; }));

    std::vector<uint32_t> ids = bvh.triangle_ids;
    std::sort(ids.begin(), ids.end());
    for (uint32_t i = 0; i < ids.size(); ++i) ASSERT_EQ(ids[i], i);
    for (size_t i = 0; i < bvh.triangles.size(); ++i) {
        const auto& tri = mesh.indices[bvh.triangle_ids[i]];
        const BvhTriangle expected{mesh.positions[tri[0]], mesh.positions[tri[1]],
                                   mesh.positions[tri[2]]};
        ASSERT_EQ(bvh.triangles[i], expected);
    }
}

TEST(BvhBuilder, EmptyInputGivesEmptyTree) {
    const Bvh bvh = build_bvh({}, {});
    EXPECT_TRUE(bvh.empty());
    EXPECT_TRUE(bvh.bounds().empty());
    EXPECT_EQ(bvh.memory_bytes(), 0u);
}

TEST(BvhBuilder, LeavesOutUnusableTriangles) {
    const float nan = std::nanf("");
    TestMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {nan, 0, 0}, {0, 0, 1}};
    mesh.indices = {
        {0, 1, 3},  // collinear
        {0, 1, 2},  // fine
        {0, 1, 4},  // NaN vertex
        {0, 1, 9},  // index out of range
        {2, 2, 2},  // a point
        {0, 2, 5},  // fine
    };
    const Bvh bvh = build(mesh);
    std::vector<uint32_t> ids = bvh.triangle_ids;
    std::sort(ids.begin(), ids.end());
    EXPECT_EQ(ids, (std::vector<uint32_t>{1, 5}));

    mesh.indices = {{0, 1, 3}, {0, 1, 4}};
    EXPECT_TRUE(build(mesh).empty());
}

TEST(BvhBuilder, SphereTreeKeepsInvariants) {
    const TestMesh mesh = testing::uv_sphere(48, 24, 1.0f);
    check_tree(build(mesh), mesh);
}

TEST(BvhBuilder, SoupTreeKeepsInvariants) {
    const TestMesh mesh = testing::random_soup(3000, 0.3f, 3);
    check_tree(build(mesh), mesh);
}

TEST(BvhBuilder, LeavesRespectMaxLeafSize) {
    const TestMesh mesh = testing::random_soup(2000, 0.2f, 5);
    BvhBuildSettings settings;
    settings.max_leaf_size = 3;
    settings.traversal_cost = 100.0f;  // the SAH would rather make big leaves
    const Bvh bvh = build(mesh, settings);
    check_tree(bvh, mesh);
    for (const BvhNode& node : bvh.nodes) EXPECT_LE(node.triangle_count, 3);
}

TEST(BvhBuilder, CoincidentTrianglesStillSplit) {
    // All centroids equal: no SAH plane separates them, so the builder halves by index.
    TestMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.indices.assign(1000, {0, 1, 2});
    const Bvh bvh = build(mesh);
    check_tree(bvh, mesh);
    for (const BvhNode& node : bvh.nodes) EXPECT_LE(node.triangle_count, 8);
}

TEST(BvhBuilder, ExtremeCoordinatesBuild) {
    // Centroids a denormal apart (bin scale K / extent overflows) and a huge mesh (areas
    // overflow): both must still give valid trees.
    TestMesh tiny;
    for (uint32_t i = 0; i < 100; ++i) {
        const float dx = float(i) * 1e-40f;
        const auto base = static_cast<uint32_t>(tiny.positions.size());
        tiny.positions.insert(tiny.positions.end(), {{dx, 0, 0}, {1 + dx, 0, 0}, {dx, 1, 0}});
        tiny.indices.push_back({base, base + 1, base + 2});
    }
    check_tree(build(tiny), tiny);

    TestMesh huge = testing::random_soup(500, 0.5f, 13);
    for (Vec3& p : huge.positions) p = p * 1e37f;
    check_tree(build(huge), huge);
}

TEST(BvhBuilder, MemoryWithinSixtyFourBytesPerTriangle) {
    const TestMesh mesh = testing::uv_sphere(128, 64, 1.0f);
    const Bvh bvh = build(mesh);
    EXPECT_LE(bvh.memory_bytes(), 64 * mesh.indices.size());
}

TEST(BvhBuilder, IdenticalForAnyThreadCount) {
    const TestMesh mesh = testing::random_soup(20000, 0.1f, 9);
    BvhBuildSettings settings;
    settings.parallel_threshold = 64;  // exercise the parallel paths on a small input
    const auto build_with = [&](int threads) {
        return tbb::task_arena(threads).execute([&] { return build(mesh, settings); });
    };
    const Bvh one = build_with(1);
    const Bvh two = build_with(2);
    ASSERT_EQ(one.nodes.size(), two.nodes.size());
    EXPECT_EQ(std::memcmp(one.nodes.data(), two.nodes.data(), one.nodes.size() * sizeof(BvhNode)),
              0);
    EXPECT_EQ(one.triangle_ids, two.triangle_ids);
    EXPECT_EQ(one.triangles, two.triangles);
}

}  // namespace
}  // namespace hikari
