#include "hikari/bench/bench_work.h"

#include <gtest/gtest.h>

#include "../ray/test_meshes.h"
#include "hikari/bench/bench_runner.h"
#include "hikari/ray/wide_bvh_builder.h"

namespace hikari {
namespace {

BenchMesh bench_mesh(const testing::TestMesh& t) {
    BenchMesh mesh{t.positions, t.indices, {}, 0};
    set_bench_bounds(mesh);
    return mesh;
}

TEST(BenchWork, CameraFollowsTheSpec) {
    const BenchMesh mesh = bench_mesh(testing::uv_sphere(96, 48, 1.0f));
    EXPECT_NEAR(mesh.diagonal, 2 * std::sqrt(3.0), 1e-6);
    const BenchRays rays = make_b1_rays(mesh, 4, 2);
    ASSERT_EQ(rays.rays.size(), 8u);
    EXPECT_FLOAT_EQ(rays.rays[0].origin.z, float(1.1 * mesh.diagonal));
    // Top-left pixel: left (-x) and up (+y); all unit length.
    EXPECT_LT(rays.rays[0].direction.x, 0.0f);
    EXPECT_GT(rays.rays[0].direction.y, 0.0f);
    for (const Ray& r : rays.rays) EXPECT_NEAR(length(r.direction), 1.0f, 1e-6);
}

/// B1 and B2 on a small mesh: the wide BVH's counts equal brute force, and do not depend on
/// the thread count.
TEST(BenchWork, ValidationValuesMatchBruteForceForAnyThreadCount) {
    const BenchMesh mesh = bench_mesh(testing::random_soup(3000, 0.2f, 77));
    const testing::TestMesh test_mesh{mesh.positions, mesh.indices};
    const WideBvh bvh = build_wide_bvh(mesh.positions, mesh.indices);
    const BenchRays b1 = make_b1_rays(mesh, 48, 48);
    std::vector<float> t1, t2;
    std::vector<uint32_t> tri1, tri2;
    trace_closest(bvh, b1, 1, 64, best_simd_level(), t1, tri1);
    trace_closest(bvh, b1, 2, 64, best_simd_level(), t2, tri2);
    EXPECT_EQ(t1, t2);
    EXPECT_EQ(tri1, tri2);
    size_t hits = 0;
    for (size_t i = 0; i < b1.rays.size(); ++i) {
        const auto expected = testing::brute_force_closest(test_mesh, b1.rays[i], {});
        ASSERT_EQ(expected.has_value(), t1[i] < k_infinity) << i;
        if (expected) ASSERT_EQ(expected->hit.t, t1[i]) << i;
        hits += expected.has_value();
    }
    EXPECT_GT(hits, 500u);

    const BenchRays b2 = make_b2_rays(mesh, b1, t1, tri1);
    EXPECT_EQ(b2.rays.size(), 4 * hits);
    std::vector<uint8_t> o1, o2;
    trace_occluded(bvh, b2, 1, 100, SimdLevel::portable, o1);
    trace_occluded(bvh, b2, 2, 100, best_simd_level(), o2);
    EXPECT_EQ(o1, o2);
    size_t occluded = 0;
    for (size_t i = 0; i < b2.rays.size(); ++i) {
        const bool expected =
            testing::brute_force_closest(test_mesh, b2.rays[i], {0.0f, b2.t_far}).has_value();
        ASSERT_EQ(expected, o1[i] != 0) << i;
        occluded += expected;
    }
    EXPECT_GT(occluded, 50u);  // the test saw both outcomes
    EXPECT_LT(occluded, b2.rays.size() - 50);
}

/// B1 as 4x4 packets: every ray's t and triangle equal the single-ray B1's, for any thread
/// count and SIMD level (a mesh much smaller than the image, so packets straddle silhouettes).
TEST(BenchWork, PacketB1EqualsSingleRayB1) {
    const BenchMesh mesh = bench_mesh(testing::random_soup(3000, 0.2f, 78));
    const WideBvh bvh = build_wide_bvh(mesh.positions, mesh.indices);
    const BenchRays b1 = make_b1_rays(mesh, 64, 64);
    std::vector<float> t_single, t_packet;
    std::vector<uint32_t> tri_single, tri_packet;
    trace_closest(bvh, b1, 1, 64, best_simd_level(), t_single, tri_single);
    for (SimdLevel level : {SimdLevel::portable, SimdLevel::avx2, SimdLevel::avx512}) {
        if (!simd_level_supported(level)) continue;
        for (int threads : {1, 2}) {
            trace_closest_packets(bvh, b1, 64, threads, 8, level, t_packet, tri_packet);
            EXPECT_EQ(t_packet, t_single) << simd_level_name(level) << " " << threads;
            EXPECT_EQ(tri_packet, tri_single) << simd_level_name(level) << " " << threads;
        }
    }
}

}  // namespace
}  // namespace hikari
