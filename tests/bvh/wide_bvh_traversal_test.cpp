#include "hikari/bvh/wide_bvh_traversal.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "hikari/bvh/wide_bvh_builder.h"
#include "hikari/bvh/wide_bvh_kernel.h"
#include "test_meshes.h"

namespace hikari {
namespace {

using testing::TestMesh;

/// The wide BVH's closest and any hit at every level against testing every triangle: same
/// miss, same t, same triangle (ties: the first in input order never matters here, so any
/// triangle hit at that t), and all levels bit-identical to each other.
void expect_matches_brute_force(const WideBvh& bvh, const TestMesh& mesh, const Ray& ray,
                                Interval valid, int ray_index) {
    const auto expected = testing::brute_force_closest(mesh, ray, valid);
    TriangleHit first_hit;
    bool first_found = false;
    bool first_level = true;
    for (SimdLevel level : supported_simd_levels()) {
        SCOPED_TRACE(simd_level_name(level));
        TriangleHit hit;
        const bool found = intersect_closest(bvh, ray, valid, hit, level);
        ASSERT_EQ(found, expected.has_value()) << "ray " << ray_index;
        ASSERT_EQ(intersect_any(bvh, ray, valid, level), found) << "ray " << ray_index;
        if (first_level) {
            first_hit = hit, first_found = found, first_level = false;
        } else if (found) {
            ASSERT_TRUE(first_found);
            EXPECT_EQ(hit.t, first_hit.t);
            EXPECT_EQ(hit.u, first_hit.u);
            EXPECT_EQ(hit.v, first_hit.v);
            EXPECT_EQ(hit.triangle, first_hit.triangle);
        }
        if (!found) continue;
        ASSERT_EQ(hit.t, expected->hit.t) << "ray " << ray_index;
        if (hit.triangle == expected->triangle) {
            EXPECT_EQ(hit.u, expected->hit.u);
            EXPECT_EQ(hit.v, expected->hit.v);
            continue;
        }
        const auto& tri = mesh.indices.at(hit.triangle);
        const auto own = intersect_triangle(ray, mesh.positions[tri[0]], mesh.positions[tri[1]],
                                            mesh.positions[tri[2]], {valid.min, k_infinity});
        ASSERT_TRUE(own) << "ray " << ray_index;
        EXPECT_EQ(own->t, hit.t) << "ray " << ray_index;
    }
}

TEST(WideBvhTraversal, LeafRayEqualsWatertightRay) {
    // The kernels' branch-free axis choice must be WatertightRay's, ties and signs included:
    // every combination of components from {0, -0, +-1, +-2} and random directions.
    const std::array<float, 6> values{0.0f, -0.0f, 1.0f, -1.0f, 2.0f, -2.0f};
    std::vector<Vec3> directions;
    for (float x : values)
        for (float y : values)
            for (float z : values) directions.push_back({x, y, z});
    Pcg32 rng(7, 3);
    for (int i = 0; i < 1000; ++i) directions.push_back(testing::random_direction(rng));
    for (const Vec3& d : directions) {
        if (d == Vec3(0.0f)) continue;
        const Ray ray{{0.5f, -1.5f, 2.5f}, d};
        const WatertightRay expected(ray);
        const WatertightRay got = wide_kernel::LeafRay(ray).watertight();
        EXPECT_TRUE(got.kx == expected.kx && got.ky == expected.ky && got.kz == expected.kz)
            << d.x << " " << d.y << " " << d.z;
        EXPECT_EQ(got.sx, expected.sx);
        EXPECT_EQ(got.sy, expected.sy);
        EXPECT_EQ(got.sz, expected.sz);
        EXPECT_EQ(got.origin, expected.origin);
    }
}

TEST(WideBvhTraversal, PortableLevelAlwaysSupported) {
    EXPECT_TRUE(simd_level_supported(SimdLevel::portable));
    EXPECT_TRUE(simd_level_supported(best_simd_level()));
}

TEST(WideBvhTraversal, EmptyTreeHitsNothing) {
    const WideBvh bvh = build_wide_bvh({}, {});
    TriangleHit hit;
    for (SimdLevel level : supported_simd_levels()) {
        EXPECT_FALSE(intersect_closest(bvh, Ray{{0, 0, 0}, {0, 0, 1}}, {}, hit, level));
        EXPECT_FALSE(intersect_any(bvh, Ray{{0, 0, 0}, {0, 0, 1}}, {}, level));
    }
}

TEST(WideBvhTraversal, ReportsInputIndexAndBarycentrics) {
    TestMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {0, 0, -1}, {1, 0, -1}};
    mesh.indices = {{0, 1, 3}, {4, 5, 2}, {0, 1, 2}};
    const WideBvh bvh = build_wide_bvh(mesh.positions, mesh.indices);
    for (SimdLevel level : supported_simd_levels()) {
        TriangleHit hit;
        ASSERT_TRUE(intersect_closest(bvh, Ray{{0.25f, 0.5f, 2}, {0, 0, -1}}, {}, hit, level));
        EXPECT_EQ(hit.triangle, 2u);
        EXPECT_FLOAT_EQ(hit.t, 2.0f);
        EXPECT_FLOAT_EQ(hit.u, 0.25f);
        EXPECT_FLOAT_EQ(hit.v, 0.5f);
    }
}

TEST(WideBvhTraversal, BadRaysHitNothing) {
    const TestMesh mesh = testing::uv_sphere(16, 8, 1.0f);
    const WideBvh bvh = build_wide_bvh(mesh.positions, mesh.indices);
    const float nan = std::nanf("");
    TriangleHit hit;
    for (SimdLevel level : supported_simd_levels())
        for (const Ray& ray : {Ray{{0, 0, -3}, {0, 0, 0}}, Ray{{0, 0, -3}, {nan, 0, 1}},
                               Ray{{nan, 0, -3}, {0, 0, 1}}, Ray{{0, 0, -3}, {0, 0, k_infinity}}}) {
            EXPECT_FALSE(intersect_closest(bvh, ray, {}, hit, level));
            EXPECT_FALSE(intersect_any(bvh, ray, {}, level));
        }
}

TEST(WideBvhTraversal, RayInBoundingBoxFacePlaneStillHits) {
    // An axis-aligned cube: rays along -z in the plane x = 1 (the box face) give 0 * inf in the
    // slab test; the top face's edge at x = 1 must still be found, at t = 1.
    TestMesh mesh;
    for (int i = 0; i < 8; ++i) mesh.positions.push_back(Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
    mesh.indices = {{4, 5, 7}, {4, 7, 6}, {0, 2, 3}, {0, 3, 1}, {1, 3, 7}, {1, 7, 5},
                    {0, 4, 6}, {0, 6, 2}, {0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3}};
    BvhBuildSettings settings;
    settings.max_leaf_size = 1;  // a deep tree, so many boxes share the face plane
    const WideBvh bvh = build_wide_bvh(mesh.positions, mesh.indices, settings);
    for (const Vec3 origin : {Vec3(1, 0.5f, 2), Vec3(1, 1, 2), Vec3(0, 0.25f, 2)}) {
        const Ray ray{origin, {0, 0, -1}};
        for (SimdLevel level : supported_simd_levels()) {
            TriangleHit hit;
            ASSERT_TRUE(intersect_closest(bvh, ray, {}, hit, level));
            EXPECT_EQ(hit.t, 1.0f);
        }
        expect_matches_brute_force(bvh, mesh, ray, {}, 0);
    }
}

TEST(WideBvhTraversal, IntervalLimitsHits) {
    const TestMesh mesh = testing::uv_sphere(16, 8, 1.0f);
    const WideBvh bvh = build_wide_bvh(mesh.positions, mesh.indices);
    const Ray ray{{0.01f, 0.02f, -3}, {0, 0, 1}};  // enters at t ~ 2, leaves at t ~ 4
    for (SimdLevel level : supported_simd_levels()) {
        TriangleHit hit;
        ASSERT_TRUE(intersect_closest(bvh, ray, {}, hit, level));
        EXPECT_NEAR(hit.t, 2.0f, 0.05f);
        ASSERT_TRUE(intersect_closest(bvh, ray, {3.0f, k_infinity}, hit, level));
        EXPECT_NEAR(hit.t, 4.0f, 0.05f);
        EXPECT_FALSE(intersect_closest(bvh, ray, {0.0f, 1.5f}, hit, level));
        EXPECT_FALSE(intersect_any(bvh, ray, {0.0f, 1.5f}, level));
        EXPECT_FALSE(intersect_any(bvh, ray, {4.5f, k_infinity}, level));
        EXPECT_TRUE(intersect_any(bvh, ray, {0.0f, 2.5f}, level));
    }
}

TEST(WideBvhTraversal, MatchesBruteForceOnRandomSoup) {
    const TestMesh mesh = testing::random_soup(3000, 0.3f, 21);
    const WideBvh bvh = build_wide_bvh(mesh.positions, mesh.indices);
    Pcg32 rng(22, 1);
    for (int i = 0; i < 3000; ++i) {
        const Ray ray{testing::random_point(rng, 1.5f), testing::random_direction(rng)};
        expect_matches_brute_force(bvh, mesh, ray, {}, i);
        if (::testing::Test::HasFatalFailure()) return;
    }
}

TEST(WideBvhTraversal, MatchesBruteForceOnSphereIncludingVertexRays) {
    const TestMesh mesh = testing::uv_sphere(64, 32, 1.0f);
    const WideBvh bvh = build_wide_bvh(mesh.positions, mesh.indices);
    Pcg32 rng(23, 1);
    for (int i = 0; i < 3000; ++i) {
        // Rays at random points, and rays aimed exactly at vertices and edge midpoints, where
        // edge functions are zero and the SIMD kernels take the exact fallback.
        const Vec3 origin =
            i % 2 ? 3.0f * testing::random_direction(rng) : testing::random_point(rng, 0.5f);
        const auto& tri = mesh.indices[rng.next_u32() % mesh.indices.size()];
        const Vec3 target = i % 3 == 0   ? testing::random_point(rng, 0.9f)
                            : i % 3 == 1 ? mesh.positions[tri[0]]
                                         : 0.5f * (mesh.positions[tri[1]] + mesh.positions[tri[2]]);
        const Ray ray{origin, normalize(target - origin)};
        expect_matches_brute_force(bvh, mesh, ray, {}, i);
        if (::testing::Test::HasFatalFailure()) return;
    }
}

TEST(WideBvhTraversal, LeavesOfMoreThanEightTrianglesMatchBruteForce) {
    // Leaves of 9 to 16 triangles: the SIMD leaf tests take them in two blocks of lanes, the
    // second one out of line.
    const TestMesh mesh = testing::random_soup(3000, 0.3f, 24);
    BvhBuildSettings settings;
    settings.max_leaf_size = WideBvhRef::k_max_leaf_size;
    const WideBvh bvh = build_wide_bvh(mesh.positions, mesh.indices, settings);
    uint32_t big_leaves = 0;
    for (const WideBvhNode& node : bvh.nodes)
        for (uint32_t child : node.child)
            if (child != WideBvhRef::k_empty && WideBvhRef::is_leaf(child) &&
                WideBvhRef::leaf_count(child) > 8)
                ++big_leaves;
    ASSERT_GT(big_leaves, 100u);
    Pcg32 rng(25, 1);
    for (int i = 0; i < 3000; ++i) {
        const Ray ray{testing::random_point(rng, 1.5f), testing::random_direction(rng)};
        const Interval valid = i % 2 ? Interval{} : Interval{0.0f, 0.3f * rng.next_float()};
        expect_matches_brute_force(bvh, mesh, ray, valid, i);
        if (::testing::Test::HasFatalFailure()) return;
    }
}

TEST(WideBvhTraversal, AxisAlignedRaysThroughGridEdges) {
    // A flat grid hit by rays along -z exactly through its shared edges and vertices: no ray
    // may slip through (watertightness survives the SIMD leaf test).
    TestMesh mesh;
    const int n = 16;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) mesh.positions.push_back(Vec3(float(x), float(y), 0));
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const auto i = static_cast<uint32_t>(y * (n + 1) + x);
            mesh.indices.push_back({i, i + 1, i + n + 2});
            mesh.indices.push_back({i, i + n + 2, i + n + 1});
        }
    const WideBvh bvh = build_wide_bvh(mesh.positions, mesh.indices);
    for (int y = 1; y < 2 * n; ++y)
        for (int x = 1; x < 2 * n; ++x) {
            const Ray ray{{0.5f * float(x), 0.5f * float(y), 1}, {0, 0, -1}};
            for (SimdLevel level : supported_simd_levels()) {
                TriangleHit hit;
                ASSERT_TRUE(intersect_closest(bvh, ray, {}, hit, level)) << x << "," << y;
                EXPECT_EQ(hit.t, 1.0f);
            }
            expect_matches_brute_force(bvh, mesh, ray, {}, y * 100 + x);
        }
}

TEST(WideBvhTraversal, AnyHitMatchesBruteForceWithinShortIntervals) {
    const TestMesh mesh = testing::random_soup(2000, 0.2f, 31);
    const WideBvh bvh = build_wide_bvh(mesh.positions, mesh.indices);
    Pcg32 rng(32, 1);
    int occluded = 0;
    for (int i = 0; i < 3000; ++i) {
        const Ray ray{testing::random_point(rng, 1.0f), testing::random_direction(rng)};
        const Interval valid{0.01f, 0.3f * rng.next_float()};
        const bool expected = testing::brute_force_closest(mesh, ray, valid).has_value();
        for (SimdLevel level : supported_simd_levels())
            ASSERT_EQ(intersect_any(bvh, ray, valid, level), expected) << "ray " << i;
        occluded += expected;
    }
    EXPECT_GT(occluded, 100);  // the test saw both outcomes
    EXPECT_LT(occluded, 2900);
}

}  // namespace
}  // namespace hikari
