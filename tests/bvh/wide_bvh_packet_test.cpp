#include "hikari/bvh/wide_bvh_packet.h"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <vector>

#include "hikari/bvh/wide_bvh_builder.h"
#include "hikari/bvh/wide_bvh_traversal.h"
#include "test_meshes.h"

namespace hikari {
namespace {

using testing::TestMesh;

WideBvh build(const TestMesh& mesh) { return build_wide_bvh(mesh.positions, mesh.indices); }

/// Checks occluded_packet against the single-ray any-hit kernel on every active lane, with every
/// group forced through the packet kernel (smallest group 1) and through the public entry;
/// returns the number of occluded lanes.
int expect_occlusion_matches_single_rays(const WideBvh& bvh, const RayPacket& packet,
                                         uint32_t active, SimdLevel level) {
    int occluded = 0;
    for (uint32_t min_group : {1u, 4u}) {
        SCOPED_TRACE(::testing::Message() << "any hit, min_group " << min_group);
        const uint32_t mask = min_group == 4
                                  ? occluded_packet(bvh, packet, active, level)
                                  : detail::occluded_packet(bvh, packet, active, level, min_group);
        EXPECT_EQ(mask & ~active, 0u);
        occluded = 0;
        for (uint32_t lane = 0; lane < k_packet_size; ++lane) {
            if (!(active & (1u << lane))) continue;
            const bool want = intersect_any(bvh, packet.ray(lane),
                                            {packet.t_min[lane], packet.t_max[lane]}, level);
            EXPECT_EQ((mask >> lane) & 1u, want ? 1u : 0u) << "lane " << lane;
            occluded += want ? 1 : 0;
        }
    }
    return occluded;
}

/// Traces `packet` at every level, through the public entry (smallest group 4) and with every
/// group forced through the packet kernel (smallest group 1), and checks every active lane
/// against the single-ray kernel: same hit or miss, same triangle, bit-identical t, u, v; and
/// the same as shadow rays (expect_occlusion_matches_single_rays). Returns the number of lanes
/// that hit.
int expect_matches_single_rays(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                               const char* what) {
    int hits = 0;
    for (SimdLevel level : supported_simd_levels()) {
        SCOPED_TRACE(::testing::Message() << what << ", " << simd_level_name(level));
        expect_occlusion_matches_single_rays(bvh, packet, active, level);
        for (uint32_t min_group : {1u, 4u}) {
            SCOPED_TRACE(::testing::Message() << "min_group " << min_group);
            PacketHit got;
            const uint32_t mask =
                detail::intersect_closest_packet(bvh, packet, active, got, level, min_group);
            EXPECT_EQ(mask & ~active, 0u);
            hits = 0;
            for (uint32_t lane = 0; lane < k_packet_size; ++lane) {
                if (!(active & (1u << lane))) continue;
                TriangleHit want;
                const bool found = intersect_closest(
                    bvh, packet.ray(lane), {packet.t_min[lane], packet.t_max[lane]}, want, level);
                EXPECT_EQ((mask >> lane) & 1u, found ? 1u : 0u) << "lane " << lane;
                if (!found || !((mask >> lane) & 1u)) continue;
                ++hits;
                EXPECT_EQ(got.triangle[lane], want.triangle) << "lane " << lane;
                EXPECT_EQ(got.t[lane], want.t) << "lane " << lane;
                EXPECT_EQ(got.u[lane], want.u) << "lane " << lane;
                EXPECT_EQ(got.v[lane], want.v) << "lane " << lane;
            }
        }
    }
    return hits;
}

/// A 4x4 block of pinhole camera rays: eye `eye`, looking down -z, pixel (px, py) of a
/// size x size image with a 60 degree field of view; directions not normalized when `raw`.
RayPacket camera_block(const Vec3& eye, int size, int px, int py, Interval valid) {
    RayPacket p{};
    const float scale = std::tan(0.5236f);
    for (uint32_t k = 0; k < k_packet_size; ++k) {
        const float x = (2.0f * (float(px + int(k % 4)) + 0.5f) / float(size) - 1.0f) * scale;
        const float y = (1.0f - 2.0f * (float(py + int(k / 4)) + 0.5f) / float(size)) * scale;
        p.set(k, {eye, normalize(Vec3(x, y, -1.0f))}, valid);
    }
    return p;
}

TEST(WideBvhPacket, CameraPacketsMatchSingleRays) {
    const TestMesh meshes[] = {testing::uv_sphere(48, 24, 1.0f),
                               testing::random_soup(2000, 0.3f, 5)};
    for (const TestMesh& mesh : meshes) {
        const WideBvh bvh = build(mesh);
        int hits = 0;
        // 64 x 64 image, every 4x4 block, including those straddling the image centre (mixed
        // direction signs, split into groups).
        for (int py = 0; py < 64; py += 4)
            for (int px = 0; px < 64; px += 4)
                hits += expect_matches_single_rays(
                    bvh, camera_block({0.1f, -0.05f, 3.0f}, 64, px, py, {}), 0xffffu, "camera");
        EXPECT_GT(hits, 500);
    }
}

TEST(WideBvhPacket, RandomIncoherentPacketsMatchSingleRays) {
    const TestMesh mesh = testing::random_soup(1500, 0.4f, 9);
    const WideBvh bvh = build(mesh);
    Pcg32 rng(42, 3);
    int hits = 0;
    for (int n = 0; n < 200; ++n) {
        RayPacket p{};
        for (uint32_t k = 0; k < k_packet_size; ++k) {
            const Vec3 o = testing::random_point(rng, 2.0f);
            p.set(k, {o, testing::random_direction(rng)}, {0.0f, 1.0f + 4.0f * rng.next_float()});
        }
        hits += expect_matches_single_rays(bvh, p, 0xffffu, "random");
    }
    EXPECT_GT(hits, 200);
}

/// Coherent directions from distinct origins (the origin interval of the frustum is not a
/// point) and per-lane intervals, some of which end before the surface.
TEST(WideBvhPacket, DistinctOriginsAndIntervalsMatchSingleRays) {
    const TestMesh mesh = testing::uv_sphere(32, 16, 1.0f);
    const WideBvh bvh = build(mesh);
    Pcg32 rng(7, 7);
    int hits = 0;
    for (int n = 0; n < 200; ++n) {
        RayPacket p{};
        const Vec3 base = testing::random_point(rng, 0.8f) + Vec3(0, 0, 3);
        const Vec3 dir = normalize(Vec3(0.1f, -0.2f, -1.0f) + testing::random_point(rng, 0.2f));
        for (uint32_t k = 0; k < k_packet_size; ++k) {
            const Vec3 o = base + testing::random_point(rng, 0.05f);
            const Vec3 d = normalize(dir + testing::random_point(rng, 0.01f));
            p.set(k, {o, d}, {0.5f * rng.next_float(), 1.5f + 3.0f * rng.next_float()});
        }
        hits += expect_matches_single_rays(bvh, p, 0xffffu, "origins");
    }
    EXPECT_GT(hits, 500);
}

TEST(WideBvhPacket, PartiallyActivePacketsIgnoreOtherLanes) {
    const TestMesh mesh = testing::uv_sphere(32, 16, 1.0f);
    const WideBvh bvh = build(mesh);
    Pcg32 rng(11, 2);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (int n = 0; n < 100; ++n) {
        RayPacket p = camera_block({0.0f, 0.0f, 3.0f}, 32, 4 * int(rng.next_u32() % 8),
                                   4 * int(rng.next_u32() % 8), {});
        const uint32_t active = rng.next_u32() & 0xffffu;
        for (uint32_t k = 0; k < k_packet_size; ++k) {
            if (active & (1u << k)) continue;
            // Garbage in the inactive lanes must not leak into the frustum or the answers.
            p.set(k, {{nan, 1e30f, -nan}, {0.0f, nan, 1e-40f}}, {nan, -1.0f});
        }
        expect_matches_single_rays(bvh, p, active, "partial");
    }
    RayPacket p = camera_block({0.0f, 0.0f, 3.0f}, 8, 2, 2, {});
    PacketHit h;
    EXPECT_EQ(intersect_closest_packet(bvh, p, 0u, h), 0u);
}

/// Directions with zero (+0 and -0) or tiny components, a zero direction, non-finite origins
/// and directions, and odd intervals: all must answer as the single-ray kernel.
TEST(WideBvhPacket, DegenerateRaysMatchSingleRays) {
    const TestMesh mesh = testing::uv_sphere(24, 12, 1.0f);
    const WideBvh bvh = build(mesh);
    const float inf = k_infinity, nan = std::numeric_limits<float>::quiet_NaN();
    const Vec3 eye{0.0f, 0.0f, 3.0f};
    const Ray special[] = {
        {eye, {0.0f, 0.0f, -1.0f}},
        {eye, {-0.0f, 0.0f, -1.0f}},
        {eye, {0.0f, -0.0f, -1.0f}},
        {eye, {1e-38f, 0.0f, -1.0f}},
        {eye, {-1e-35f, 1e-33f, -1.0f}},
        {eye, {0.0f, 0.0f, 0.0f}},
        {eye, {nan, 0.0f, -1.0f}},
        {eye, {inf, 0.0f, -1.0f}},
        {{inf, 0.0f, 3.0f}, {0.0f, 0.0f, -1.0f}},
        {{0.0f, nan, 3.0f}, {0.0f, 0.0f, -1.0f}},
        {{0.0f, 3.0f, 0.0f}, {0.0f, -1.0f, 0.0f}},
        {{3.0f, 0.0f, 0.0f}, {-1.0f, 0.0f, 0.0f}},
        {{0.3f, 0.2f, 3.0f}, {0.0f, 0.0f, -2.0f}},
        {{0.3f, 0.2f, 3.0f}, {0.0f, 0.0f, -1e-20f}},
        {{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}},
        {{0.5f, 0.0f, 3.0f}, {-0.0f, -0.0f, -3.0f}},
    };
    RayPacket p{};
    for (uint32_t k = 0; k < k_packet_size; ++k) p.set(k, special[k], {});
    EXPECT_GE(expect_matches_single_rays(bvh, p, 0xffffu, "degenerate"), 8);

    // The same rays with odd intervals.
    const Interval intervals[] = {{nan, inf}, {0.0f, nan}, {2.5f, 2.0f}, {-inf, inf}};
    for (uint32_t k = 0; k < k_packet_size; ++k) p.set(k, special[k], intervals[k % 4]);
    expect_matches_single_rays(bvh, p, 0xffffu, "intervals");

    // A packet of only axis-aligned rays along -z with zero x and y: one group, one octant
    // chosen by the sign of zero.
    for (uint32_t k = 0; k < k_packet_size; ++k)
        p.set(k,
              {{0.1f * float(k % 4) - 0.15f, 0.1f * float(k / 4) - 0.15f, 3.0f},
               {k % 2 ? -0.0f : 0.0f, 0.0f, -1.0f}},
              {});
    EXPECT_EQ(expect_matches_single_rays(bvh, p, 0xffffu, "axis-aligned"), 16);
}

/// Rays through mesh vertices meet several triangles at the same t (edge functions exactly
/// zero, the exact fallback, and ties the single-ray kernel breaks by its visiting order); a
/// mesh with every triangle twice makes every hit a tie.
TEST(WideBvhPacket, VerticesEdgesAndTiesMatchSingleRays) {
    TestMesh mesh = testing::uv_sphere(16, 8, 1.0f);
    const WideBvh bvh = build(mesh);
    TestMesh doubled = mesh;
    for (const auto& tri : mesh.indices) doubled.indices.push_back(tri);
    const WideBvh bvh_doubled = build(doubled);
    const Vec3 eye{0.05f, 0.1f, 4.0f};
    int hits = 0;
    for (size_t first = 0; first + k_packet_size <= mesh.positions.size(); first += 4) {
        RayPacket p{};
        for (uint32_t k = 0; k < k_packet_size; ++k) {
            const Vec3 target = mesh.positions[first + k];
            p.set(k, {eye, target - eye}, {});
        }
        hits += expect_matches_single_rays(bvh, p, 0xffffu, "vertices");
        hits += expect_matches_single_rays(bvh_doubled, p, 0xffffu, "doubled");
    }
    EXPECT_GT(hits, 100);
    for (int py = 0; py < 16; py += 4)
        for (int px = 0; px < 16; px += 4)
            expect_matches_single_rays(bvh_doubled, camera_block(eye, 16, px, py, {}), 0xffffu,
                                       "doubled camera");
}

/// A root with two leaves and the given boxes (which must hold their triangles). Leaf i holds
/// triangles `leaves[i]` (three vertices each), with input indices numbered in order.
WideBvh two_leaf_tree(const std::array<std::vector<std::array<Vec3, 3>>, 2>& leaves,
                      const std::array<Aabb, 2>& boxes) {
    WideBvh bvh;
    WideBvhNode root{};
    for (uint32_t slot = 0; slot < k_wide_bvh_width; ++slot) {
        const Aabb box = slot < 2 ? boxes[slot] : Aabb{};
        for (int a = 0; a < 3; ++a) {
            root.bounds[2 * a][slot] = box.min[a];
            root.bounds[2 * a + 1][slot] = box.max[a];
        }
        root.child[slot] = WideBvhRef::k_empty;
    }
    uint32_t first = 0;
    for (uint32_t i = 0; i < 2; ++i) {
        const auto count = static_cast<uint32_t>(leaves[i].size());
        root.child[i] = WideBvhRef::leaf(first, count);
        for (int row = 0; row < 9; ++row)
            for (const auto& triangle : leaves[i])
                bvh.triangle_data.push_back(triangle[row / 3][row % 3]);
        for (uint32_t k = 0; k < count; ++k) bvh.triangle_ids.push_back(first + k);
        first += count;
    }
    bvh.triangle_data.resize(bvh.triangle_data.size() + 8, 0.0f);
    bvh.nodes.push_back(root);
    bvh.root = WideBvhRef::inner(0);
    bvh.root_bounds = boxes[0];
    bvh.root_bounds.extend(boxes[1]);
    return bvh;
}

/// Two leaves hold the same triangle, so a ray meets both copies at exactly the same t, and the
/// single-ray kernel reports the copy in the leaf it enters first. Each of two rays starts
/// inside one leaf's box and enters the other's later, so their orders differ; the packet's
/// frustum enters both boxes at once and takes them in slot order. The packet kernel must hand
/// the tied lane back (GroupHits::ties). With and without other triangles in the leaves.
TEST(WideBvhPacket, TiesBetweenLeavesMatchSingleRays) {
    const std::array<Vec3, 3> shared{Vec3{-2, -2, 0}, Vec3{4, -2, 0}, Vec3{-2, 4, 0}};
    const std::array<Aabb, 2> boxes{Aabb{{-10, -2, 0}, {4, 4, 25}}, Aabb{{-2, -10, 0}, {4, 4, 25}}};
    // Rays toward (0.5, 0.5, 0), from inside box 0 only (lane 0) and inside box 1 only (lane 1).
    RayPacket packet{};
    const Vec3 target{0.5f, 0.5f, 0.0f};
    packet.set(0, {{-8.0f, 0.0f, 20.0f}, target - Vec3{-8.0f, 0.0f, 20.0f}}, {});
    packet.set(1, {{0.0f, -8.0f, 20.0f}, target - Vec3{0.0f, -8.0f, 20.0f}}, {});
    for (const uint32_t fillers : {0u, 2u}) {
        std::array<std::vector<std::array<Vec3, 3>>, 2> leaves;
        for (auto& leaf : leaves) {
            leaf.push_back(shared);
            for (uint32_t k = 0; k < fillers; ++k) {
                const float x = 3.0f + 0.3f * float(k);  // inside the boxes, on neither ray
                leaf.push_back(
                    {Vec3{x, 3.0f, 0.0f}, Vec3{x + 0.2f, 3.0f, 0.0f}, Vec3{x, 3.2f, 0.0f}});
            }
        }
        const WideBvh bvh = two_leaf_tree(leaves, boxes);
        SCOPED_TRACE(::testing::Message() << fillers << " other triangles per leaf");
        TriangleHit hit0, hit1;
        ASSERT_TRUE(intersect_closest(bvh, packet.ray(0), {}, hit0));
        ASSERT_TRUE(intersect_closest(bvh, packet.ray(1), {}, hit1));
        EXPECT_NE(hit0.triangle, hit1.triangle);  // the rays' own orders differ
        EXPECT_EQ(expect_matches_single_rays(bvh, packet, 0b11u, "tied leaves"), 2);
    }
}

/// Shadow rays as the ray tracer makes them: from the visible points of a mesh toward one
/// point light, in rows of 16 pixels, with a cloud of triangles between the mesh and the light.
/// Some lanes are blocked and some are not, and each answers as its single ray does.
TEST(WideBvhPacket, ShadowRaysTowardALightMatchSingleRays) {
    TestMesh mesh = testing::uv_sphere(40, 20, 1.0f);
    const TestMesh soup = testing::random_soup(300, 0.15f, 4);
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    for (const Vec3& p : soup.positions)
        mesh.positions.push_back(p * 0.6f + Vec3(0.9f, 1.2f, 0.9f));
    for (const auto& t : soup.indices)
        mesh.indices.push_back({t[0] + base, t[1] + base, t[2] + base});
    const WideBvh bvh = build(mesh);
    const Vec3 eye{0.0f, 0.0f, 3.0f}, light{2.0f, 3.0f, 2.5f};
    int rays = 0, occluded = 0;
    for (int y = 0; y < 32; ++y) {
        RayPacket shadows{};
        uint32_t active = 0;
        for (uint32_t x = 0; x < k_packet_size; ++x) {
            const Vec3 d = normalize(Vec3(float(x) / 16.0f - 0.5f, 0.5f - float(y) / 32.0f, -1.0f));
            TriangleHit hit;
            if (!intersect_closest(bvh, {eye, d}, {}, hit)) continue;
            const Vec3 p = eye + d * hit.t;
            const Vec3 to_light = light - p;
            const float distance = length(to_light);
            const Vec3 l = to_light / distance;
            shadows.set(x, {p + l * 1e-3f, l}, {0.0f, distance});
            active |= 1u << x;
        }
        for (SimdLevel level : supported_simd_levels())
            occluded += expect_occlusion_matches_single_rays(bvh, shadows, active, level);
        rays += std::popcount(active) * int(supported_simd_levels().size());
    }
    EXPECT_GT(occluded, rays / 10);
    EXPECT_LT(occluded, rays - rays / 10);
}

TEST(WideBvhPacket, EmptyTreeHitsNothing) {
    const WideBvh empty;
    const RayPacket p = camera_block({0, 0, 3}, 8, 0, 0, {});
    for (SimdLevel level : supported_simd_levels()) {
        PacketHit h;
        EXPECT_EQ(intersect_closest_packet(empty, p, 0xffffu, h, level), 0u);
        EXPECT_EQ(occluded_packet(empty, p, 0xffffu, level), 0u);
    }
    std::vector<Ray> rays(9, Ray{{0, 0, 3}, {0, 0, -1}});
    std::vector<TriangleHit> hits(9);
    std::vector<uint8_t> found(9, 7);
    intersect_closest_tile(empty, rays.data(), 3, 3, 3, {}, hits.data(), found.data());
    for (uint8_t f : found) EXPECT_EQ(f, 0);
}

/// A tile whose size is no multiple of 4, inside a wider image: every ray of the tile answered
/// as by the single-ray kernel, nothing outside it touched.
TEST(WideBvhPacket, TileMatchesSingleRays) {
    const TestMesh mesh = testing::uv_sphere(40, 20, 1.0f);
    const WideBvh bvh = build(mesh);
    const int width = 37, height = 23, stride = 41, rows = 25;
    std::vector<Ray> rays(size_t(stride) * rows);
    for (int y = 0; y < rows; ++y)
        for (int x = 0; x < stride; ++x) {
            const float sx = (2.0f * (float(x) + 0.5f) / float(stride) - 1.0f) * 0.5f;
            const float sy = (1.0f - 2.0f * (float(y) + 0.5f) / float(rows)) * 0.5f;
            rays[size_t(y) * stride + x] = {{0.0f, 0.0f, 3.0f}, normalize(Vec3(sx, sy, -1.0f))};
        }
    const Interval valid{0.5f, 100.0f};
    for (SimdLevel level : supported_simd_levels()) {
        SCOPED_TRACE(simd_level_name(level));
        std::vector<TriangleHit> hits(rays.size(), TriangleHit{-1, -1, -1, 12345});
        std::vector<uint8_t> found(rays.size(), 7);
        intersect_closest_tile(bvh, rays.data() + stride + 2, stride, width, height, valid,
                               hits.data() + stride + 2, found.data() + stride + 2, level);
        int hit_count = 0;
        for (int y = 0; y < rows; ++y)
            for (int x = 0; x < stride; ++x) {
                const size_t i = size_t(y) * stride + x;
                const bool inside = y >= 1 && y < 1 + height && x >= 2 && x < 2 + width;
                if (!inside) {
                    EXPECT_EQ(found[i], 7) << x << " " << y;
                    continue;
                }
                TriangleHit want;
                const bool f = intersect_closest(bvh, rays[i], valid, want, level);
                ASSERT_EQ(found[i], f ? 1 : 0) << x << " " << y;
                if (!f) continue;
                ++hit_count;
                EXPECT_EQ(hits[i].triangle, want.triangle);
                EXPECT_EQ(hits[i].t, want.t);
                EXPECT_EQ(hits[i].u, want.u);
                EXPECT_EQ(hits[i].v, want.v);
            }
        EXPECT_GT(hit_count, 300);
    }
}

}  // namespace
}  // namespace hikari
