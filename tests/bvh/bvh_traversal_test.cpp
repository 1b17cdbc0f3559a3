#include "hikari/bvh/bvh_traversal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hikari/bvh/bvh_builder.h"
#include "test_meshes.h"

namespace hikari {
namespace {

using testing::TestMesh;

/// Checks the BVH's closest hit against testing every triangle: same miss, same t, and the same
/// triangle unless another one lies at exactly the same distance.
void expect_matches_brute_force(const Bvh& bvh, const TestMesh& mesh, const Ray& ray,
                                Interval valid, int ray_index) {
    const auto expected = testing::brute_force_closest(mesh, ray, valid);
    TriangleHit hit;
    const bool found = intersect_closest(bvh, ray, valid, hit);
    ASSERT_EQ(found, expected.has_value()) << "ray " << ray_index;
    ASSERT_EQ(intersect_any(bvh, ray, valid), found) << "ray " << ray_index;
    if (!found) return;
    ASSERT_EQ(hit.t, expected->hit.t) << "ray " << ray_index;
    if (hit.triangle == expected->triangle) {
        EXPECT_EQ(hit.u, expected->hit.u);
        EXPECT_EQ(hit.v, expected->hit.v);
        return;
    }
    // An exact tie: the reported triangle must itself be hit at that same distance.
    const auto& tri = mesh.indices.at(hit.triangle);
    const auto own = intersect_triangle(ray, mesh.positions[tri[0]], mesh.positions[tri[1]],
                                        mesh.positions[tri[2]], {valid.min, k_infinity});
    ASSERT_TRUE(own) << "ray " << ray_index;
    EXPECT_EQ(own->t, hit.t) << "ray " << ray_index;
}

TEST(BvhTraversal, EmptyTreeHitsNothing) {
    const Bvh bvh = build_bvh({}, {});
    TriangleHit hit;
    const Ray ray{{0, 0, 0}, {0, 0, 1}};
    EXPECT_FALSE(intersect_closest(bvh, ray, {}, hit));
    EXPECT_FALSE(intersect_any(bvh, ray, {}));
}

TEST(BvhTraversal, ReportsInputIndexAndBarycentrics) {
    TestMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {0, 0, -1}, {1, 0, -1}};
    mesh.indices = {{0, 1, 3}, {4, 5, 2}, {0, 1, 2}};  // a degenerate one first
    const Bvh bvh = build_bvh(mesh.positions, mesh.indices);
    TriangleHit hit;
    ASSERT_TRUE(intersect_closest(bvh, Ray{{0.25f, 0.5f, 2}, {0, 0, -1}}, {}, hit));
    EXPECT_EQ(hit.triangle, 2u);
    EXPECT_FLOAT_EQ(hit.t, 2.0f);
    EXPECT_FLOAT_EQ(hit.u, 0.25f);
    EXPECT_FLOAT_EQ(hit.v, 0.5f);
}

TEST(BvhTraversal, IntervalLimitsHits) {
    const TestMesh mesh = testing::uv_sphere(16, 8, 1.0f);
    const Bvh bvh = build_bvh(mesh.positions, mesh.indices);
    const Ray ray{{0.01f, 0.02f, -3}, {0, 0, 1}};  // enters at t ~ 2, leaves at t ~ 4
    TriangleHit hit;
    ASSERT_TRUE(intersect_closest(bvh, ray, {}, hit));
    EXPECT_NEAR(hit.t, 2.0f, 0.05f);
    ASSERT_TRUE(intersect_closest(bvh, ray, {3.0f, k_infinity}, hit));
    EXPECT_NEAR(hit.t, 4.0f, 0.05f);
    EXPECT_FALSE(intersect_closest(bvh, ray, {0.0f, 1.5f}, hit));
    EXPECT_FALSE(intersect_any(bvh, ray, {0.0f, 1.5f}));
    EXPECT_FALSE(intersect_any(bvh, ray, {4.5f, k_infinity}));
    EXPECT_TRUE(intersect_any(bvh, ray, {0.0f, 2.5f}));
}

TEST(BvhTraversal, BadRaysHitNothing) {
    const TestMesh mesh = testing::uv_sphere(16, 8, 1.0f);
    const Bvh bvh = build_bvh(mesh.positions, mesh.indices);
    const float nan = std::nanf("");
    TriangleHit hit;
    for (const Ray& ray : {Ray{{0, 0, -3}, {0, 0, 0}}, Ray{{0, 0, -3}, {nan, 0, 1}},
                           Ray{{nan, 0, -3}, {0, 0, 1}}, Ray{{0, 0, -3}, {0, 0, k_infinity}}}) {
        EXPECT_FALSE(intersect_closest(bvh, ray, {}, hit));
        EXPECT_FALSE(intersect_any(bvh, ray, {}));
    }
}

TEST(BvhTraversal, RayInBoundingBoxFacePlaneStillHits) {
    // An axis-aligned cube: rays along -z in the plane x = 1 (the box face) give 0 * inf in the
    // slab test; the top face's edge at x = 1 must still be found, at t = 1.
    TestMesh mesh;
    for (int i = 0; i < 8; ++i) mesh.positions.push_back(Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
    mesh.indices = {{4, 5, 7}, {4, 7, 6}, {0, 2, 3}, {0, 3, 1}, {1, 3, 7}, {1, 7, 5},
                    {0, 4, 6}, {0, 6, 2}, {0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3}};
    BvhBuildSettings settings;
    settings.max_leaf_size = 1;
    settings.traversal_cost = 0.0f;  // a deep tree, so many boxes share the face plane
    const Bvh bvh = build_bvh(mesh.positions, mesh.indices, settings);
    for (const Vec3 origin : {Vec3(1, 0.5f, 2), Vec3(1, 1, 2), Vec3(0, 0.25f, 2)}) {
        const Ray ray{origin, {0, 0, -1}};
        TriangleHit hit;
        ASSERT_TRUE(intersect_closest(bvh, ray, {}, hit));
        EXPECT_EQ(hit.t, 1.0f);
        expect_matches_brute_force(bvh, mesh, ray, {}, 0);
    }
}

TEST(BvhTraversal, MatchesBruteForceOnRandomSoup) {
    const TestMesh mesh = testing::random_soup(2000, 0.3f, 21);
    const Bvh bvh = build_bvh(mesh.positions, mesh.indices);
    Pcg32 rng(22, 1);
    for (int i = 0; i < 3000; ++i) {
        const Ray ray{testing::random_point(rng, 1.5f), testing::random_direction(rng)};
        expect_matches_brute_force(bvh, mesh, ray, {}, i);
        if (::testing::Test::HasFatalFailure()) return;
    }
}

TEST(BvhTraversal, MatchesBruteForceOnSphere) {
    const TestMesh mesh = testing::uv_sphere(64, 32, 1.0f);
    const Bvh bvh = build_bvh(mesh.positions, mesh.indices);
    Pcg32 rng(23, 1);
    for (int i = 0; i < 3000; ++i) {
        // Rays from outside aimed at the sphere, and rays from inside.
        const Vec3 origin =
            i % 2 ? 3.0f * testing::random_direction(rng) : testing::random_point(rng, 0.5f);
        const Vec3 target = testing::random_point(rng, 0.9f);
        const Ray ray{origin, normalize(target - origin)};
        expect_matches_brute_force(bvh, mesh, ray, {}, i);
        if (::testing::Test::HasFatalFailure()) return;
    }
}

TEST(BvhTraversal, AnyHitMatchesBruteForceWithinShortIntervals) {
    const TestMesh mesh = testing::random_soup(2000, 0.2f, 31);
    const Bvh bvh = build_bvh(mesh.positions, mesh.indices);
    Pcg32 rng(32, 1);
    int occluded = 0;
    for (int i = 0; i < 3000; ++i) {
        const Ray ray{testing::random_point(rng, 1.0f), testing::random_direction(rng)};
        const Interval valid{0.01f, 0.3f * rng.next_float()};
        const bool expected = testing::brute_force_closest(mesh, ray, valid).has_value();
        ASSERT_EQ(intersect_any(bvh, ray, valid), expected) << "ray " << i;
        occluded += expected;
    }
    EXPECT_GT(occluded, 100);  // the test saw both outcomes
    EXPECT_LT(occluded, 2900);
}

}  // namespace
}  // namespace hikari
