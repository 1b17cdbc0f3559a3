#include "hikari/bench/bench_work.h"

#include <gtest/gtest.h>

#include <array>
#include <bit>

#include "../bvh/test_meshes.h"
#include "hikari/bench/bench_runner.h"
#include "hikari/bvh/wide_bvh_builder.h"

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

/// B2's rays equal the peer's bit for bit (embree_bench, built as ../bench/peers/Makefile builds
/// it, on the bunny): pixels where both found the same hit, chosen where evaluating SPEC §4 without
/// fused multiply-adds gives different origins or directions.
TEST(BenchWork, OcclusionRaysEqualThePeersBitForBit) {
    struct PeerPixel {
        size_t pixel;
        uint32_t triangle;
        float t;
        float rays[4][6];  ///< origin, direction
    };
    // clang-format off
    const PeerPixel peer[] = {
    {190963, 61244, 0x1.335168p-2, {{-0x1.4409dcp-6, 0x1.7e2786p-3, -0x1.0dc45cp-6, -0x1.140d98p-1, 0x1.99e35ep-1, -0x1.0bcf0ep-2}, {-0x1.4409dcp-6, 0x1.7e2786p-3, -0x1.0dc45cp-6, 0x1.160024p-1, 0x1.add258p-1, -0x1.54395ap-6}, {-0x1.4409dcp-6, 0x1.7e2786p-3, -0x1.0dc45cp-6, 0x1.a7a1c8p-2, 0x1.90fd94p-3, 0x1.c73936p-1}, {-0x1.4409dcp-6, 0x1.7e2786p-3, -0x1.0dc45cp-6, 0x1.8deff8p-1, 0x1.ed012ep-3, 0x1.29a7e6p-1}}},
    {280963, 16932, 0x1.18bf2cp-2, {{-0x1.66f888p-5, 0x1.4b081ap-3, 0x1.7da93cp-8, 0x1.726652p-3, 0x1.566db4p-2, 0x1.d98e3cp-1}, {-0x1.66f888p-5, 0x1.4b081ap-3, 0x1.7da93cp-8, 0x1.459b0ap-2, -0x1.d9f282p-1, 0x1.a3c66cp-3}, {-0x1.66f888p-5, 0x1.4b081ap-3, 0x1.7da93cp-8, -0x1.f2b1b8p-3, 0x1.86b5bcp-6, 0x1.f07052p-1}, {-0x1.66f888p-5, 0x1.4b081ap-3, 0x1.7da93cp-8, -0x1.16cc02p-1, 0x1.89a026p-1, 0x1.575de4p-2}}},
    {370963, 14701, 0x1.f3482ep-3, {{-0x1.fe7f66p-5, 0x1.1c7b4p-3, 0x1.26b82ap-5, 0x1.875bf6p-4, -0x1.6b3632p-2, 0x1.dc3434p-1}, {-0x1.fe7f66p-5, 0x1.1c7b4p-3, 0x1.26b82ap-5, 0x1.c32ac6p-1, -0x1.c0171ap-6, 0x1.e34e5cp-2}, {-0x1.fe7f66p-5, 0x1.1c7b4p-3, 0x1.26b82ap-5, 0x1.f5819p-1, -0x1.ec1cdap-4, 0x1.4b1952p-3}, {-0x1.fe7f66p-5, 0x1.1c7b4p-3, 0x1.26b82ap-5, -0x1.904e22p-2, -0x1.41e268p-1, 0x1.58331cp-1}}},
    {460963, 34716, 0x1.dbce4cp-3, {{-0x1.46fc62p-4, 0x1.f0b03cp-4, 0x1.9cdbap-5, -0x1.975842p-1, -0x1.2b44e8p-1, -0x1.463e78p-3}, {-0x1.46fc62p-4, 0x1.f0b03cp-4, 0x1.9cdbap-5, -0x1.fba52ep-1, -0x1.0fb528p-4, -0x1.caa532p-4}, {-0x1.46fc62p-4, 0x1.f0b03cp-4, 0x1.9cdbap-5, -0x1.2a5a5cp-2, -0x1.d12b28p-2, 0x1.af0a12p-1}, {-0x1.46fc62p-4, 0x1.f0b03cp-4, 0x1.9cdbap-5, -0x1.0b745cp-2, -0x1.33b29p-1, 0x1.82c28cp-1}}},
    {551083, 39693, 0x1.0c58c4p-2, {{-0x1.62119p-4, 0x1.ad0edep-4, 0x1.5a8174p-6, -0x1.c7e246p-1, -0x1.c026p-2, 0x1.0044d4p-3}, {-0x1.62119p-4, 0x1.ad0edep-4, 0x1.5a8174p-6, -0x1.bf18aep-3, 0x1.e7582ap-1, 0x1.b8d5f6p-3}, {-0x1.62119p-4, 0x1.ad0edep-4, 0x1.5a8174p-6, -0x1.be1444p-2, 0x1.f267b2p-2, -0x1.83adf8p-1}, {-0x1.62119p-4, 0x1.ad0edep-4, 0x1.5a8174p-6, -0x1.585a28p-1, 0x1.7867ecp-3, 0x1.6f078p-1}}},
    {641190, 40538, 0x1.0a2e82p-2, {{-0x1.628c8ap-4, 0x1.648ae6p-4, 0x1.8f9266p-6, -0x1.d5cb3ap-2, -0x1.53a118p-1, 0x1.2eafdcp-1}, {-0x1.628c8ap-4, 0x1.648ae6p-4, 0x1.8f9266p-6, -0x1.3f3e1p-3, -0x1.15b8d2p-6, 0x1.f9aab4p-1}, {-0x1.628c8ap-4, 0x1.648ae6p-4, 0x1.8f9266p-6, -0x1.f1da64p-1, 0x1.04d52p-4, -0x1.cbf87ap-3}, {-0x1.628c8ap-4, 0x1.648ae6p-4, 0x1.8f9266p-6, -0x1.73d376p-1, -0x1.398c9ap-2, 0x1.3b22fep-1}}},
    {731358, 64408, 0x1.07dc96p-2, {{-0x1.32b86ep-4, 0x1.1cde5p-4, 0x1.a9c3c4p-6, -0x1.95c8bap-3, -0x1.f5d556p-1, 0x1.000c92p-7}, {-0x1.32b86ep-4, 0x1.1cde5p-4, 0x1.a9c3c4p-6, -0x1.c933acp-1, 0x1.75f38ep-3, 0x1.a5493cp-2}, {-0x1.32b86ep-4, 0x1.1cde5p-4, 0x1.a9c3c4p-6, -0x1.6ba11p-2, -0x1.595052p-1, 0x1.4b6e18p-1}, {-0x1.32b86ep-4, 0x1.1cde5p-4, 0x1.a9c3c4p-6, -0x1.82b0eep-1, -0x1.218c42p-1, 0x1.53450cp-2}}},
    {821549, 45460, 0x1.1fd9e4p-2, {{-0x1.0152ep-4, 0x1.7ed1ecp-5, 0x1.edc8a4p-9, 0x1.35644cp-3, 0x1.40c83cp-1, -0x1.877c04p-1}, {-0x1.0152ep-4, 0x1.7ed1ecp-5, 0x1.edc8a4p-9, -0x1.a9e4dcp-1, 0x1.b09b54p-3, -0x1.06cbaap-1}, {-0x1.0152ep-4, 0x1.7ed1ecp-5, 0x1.edc8a4p-9, -0x1.33734cp-1, 0x1.2ce67ap-1, 0x1.15a0c4p-1}, {-0x1.0152ep-4, 0x1.7ed1ecp-5, 0x1.edc8a4p-9, 0x1.3e4b6ap-2, 0x1.330f1ep-1, -0x1.798856p-1}}}
    };
    // clang-format on
    const BenchMesh mesh = load_bench_mesh(HIKARI_SOURCE_DIR "/scenes/models/stanford-bunny.obj");
    const BenchRays b1 = make_b1_rays(mesh, 1024, 1024);
    std::vector<float> hit_t(b1.rays.size(), k_infinity);
    std::vector<uint32_t> hit_triangle(b1.rays.size(), ~0u);
    for (const PeerPixel& p : peer) {
        hit_t[p.pixel] = p.t;
        hit_triangle[p.pixel] = p.triangle;
    }
    const BenchRays b2 = make_b2_rays(mesh, b1, hit_t, hit_triangle);
    ASSERT_EQ(b2.rays.size(), 4 * std::size(peer));
    for (size_t k = 0; k < b2.rays.size(); ++k) {
        const Ray& r = b2.rays[k];
        const std::array<float, 6> ours{r.origin.x,    r.origin.y,    r.origin.z,
                                        r.direction.x, r.direction.y, r.direction.z};
        for (int c = 0; c < 6; ++c)
            EXPECT_EQ(std::bit_cast<uint32_t>(ours[c]),
                      std::bit_cast<uint32_t>(peer[k / 4].rays[k % 4][c]))
                << "pixel " << peer[k / 4].pixel << " ray " << k % 4 << " component " << c;
    }
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
