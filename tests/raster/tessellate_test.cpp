#include "hikari/raster/tessellate.h"

#include <cmath>
#include <map>
#include <numbers>
#include <tuple>
#include <utility>

#include <gtest/gtest.h>

#include "hikari/core/aabb.h"
#include "hikari/geometry/surface_uv.h"
#include "hikari/raster/cull.h"
#include "raster_test_util.h"

namespace hikari {
namespace {

TEST(Tessellate, SphereIsClosedAndWoundOutward) {
    TriangleSet t;
    const Sphere s{{1, 2, 3}, 2.0f, 0, 7};
    tessellate_sphere(s, 24, t);
    // Vertices that differ only in texture coordinates (the seam's and poles' copies) are one
    // point of the surface: weld them by position.
    std::map<std::tuple<float, float, float>, uint32_t> welded;
    auto weld = [&](uint32_t v) {
        const Vec3 p = t.positions[v];
        return welded.emplace(std::tuple{p.x, p.y, p.z}, v).first->second;
    };
    std::map<std::pair<uint32_t, uint32_t>, int> edges;  // directed edge → count
    for (size_t k = 0; k < t.size(); ++k) {
        const std::array<uint32_t, 3> i{weld(t.indices[k][0]), weld(t.indices[k][1]),
                                        weld(t.indices[k][2])};
        const Vec3 n = face_normal(t.positions[i[0]], t.positions[i[1]], t.positions[i[2]]);
        EXPECT_GT(dot(n, t.positions[i[0]] - s.center), 0.0f);
        EXPECT_EQ(t.id[k], 7u);
        for (int e = 0; e < 3; ++e) ++edges[{i[e], i[(e + 1) % 3]}];
    }
    // Closed and consistently oriented: every directed edge once, its reverse once.
    for (const auto& [e, count] : edges) {
        EXPECT_EQ(count, 1);
        EXPECT_EQ(edges.count({e.second, e.first}), 1u);
    }
    for (const Vec3& p : t.positions) EXPECT_NEAR(length(p - s.center), 2.0f, 1e-5f);
}

TEST(Tessellate, SphereUvsFollowTheRayTracersMapping) {
    TriangleSet t;
    const Sphere s{{1, 2, 3}, 2.0f, 0, 7};
    tessellate_sphere(s, 30, t);  // 30: the seam (−z) falls inside a band of triangles
    ASSERT_EQ(t.uvs.size(), t.positions.size());
    int across_seam = 0;
    for (const auto& tri : t.indices) {
        float lo = 2, hi = -1;
        for (const uint32_t k : tri) {
            const SurfaceUv expected = sphere_uv(s, t.positions[k]);
            EXPECT_NEAR(t.uvs[k].y, expected.uv.y, 1e-5f);
            const bool pole = std::abs(t.uvs[k].y - 0.5f) > 0.4999f;
            if (pole) continue;
            // Equal to the mapping, or one more where the triangle straddles the seam.
            const float du = t.uvs[k].x - expected.uv.x;
            EXPECT_TRUE(std::abs(du) < 1e-5f || std::abs(du - 1.0f) < 1e-5f) << du;
            lo = std::min(lo, t.uvs[k].x), hi = std::max(hi, t.uvs[k].x);
            across_seam += t.uvs[k].x > 1.0f;
        }
        // No triangle spans the whole texture: the seam is cut, not smeared across.
        EXPECT_LT(hi - lo, 0.1f);
        // A pole corner takes the mean u of its two ring corners.
        for (int c = 0; c < 3; ++c)
            if (std::abs(t.uvs[tri[c]].y - 0.5f) > 0.4999f)
                EXPECT_NEAR(t.uvs[tri[c]].x,
                            0.5f * (t.uvs[tri[(c + 1) % 3]].x + t.uvs[tri[(c + 2) % 3]].x), 1e-6f);
    }
    EXPECT_GT(across_seam, 0);
}

TEST(Tessellate, PlaneUvsAreThePlanarMapping) {
    TriangleSet t;
    Plane p{{1, -1, 2}, normalize(Vec3(0.2f, 1, 0.1f)), 0, 3};
    p.uv_scale = 0.5f;
    tessellate_plane(p, {5, 2, 5}, 100.0f, t);
    ASSERT_EQ(t.uvs.size(), t.positions.size());
    for (size_t k = 0; k < t.positions.size(); ++k) {
        const Vec2 expected = plane_uv(p, t.positions[k]).uv;
        EXPECT_NEAR(t.uvs[k].x, expected.x, 1e-6f * (1 + std::abs(expected.x)));
        EXPECT_NEAR(t.uvs[k].y, expected.y, 1e-6f * (1 + std::abs(expected.y)));
    }
}

TEST(Tessellate, SphereSegmentsFollowProjectedSize) {
    EXPECT_EQ(sphere_segments(0.5f), 16u);
    EXPECT_LT(sphere_segments(50), sphere_segments(400));
    EXPECT_EQ(sphere_segments(1e9f), 512u);
    // 0.05 px sagitta at 200 px radius.
    const float n = static_cast<float>(sphere_segments(200));
    EXPECT_LT(200 * (1 - std::cos(std::numbers::pi_v<float> / n)), 0.05f);
}

TEST(Tessellate, PlaneGridFacesAlongNormalAndCoversTheFoot) {
    TriangleSet t;
    const Plane p{{0, -1, 0}, {0, 1, 0}, 0, 3};
    tessellate_plane(p, {5, 2, 5}, 1000.0f, t);
    Aabb box;
    for (const Vec3& v : t.positions) {
        EXPECT_FLOAT_EQ(v.y, -1.0f);
        box.extend(v);
    }
    EXPECT_FLOAT_EQ(box.min.x, 5 - 1000.0f);
    EXPECT_FLOAT_EQ(box.max.z, 5 + 1000.0f);
    for (const auto& i : t.indices)
        EXPECT_GT(face_normal(t.positions[i[0]], t.positions[i[1]], t.positions[i[2]]).y, 0.0f);
}

TEST(Tessellate, SceneOrderFollowsPrimitiveIds) {
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "width": 64, "height": 64},
      "objects": [
        {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]},
        {"type": "sphere", "center": [0, 0, 0], "radius": 1},
        {"type": "triangle", "vertices": [[0, 0, 1], [1, 0, 1], [0, 1, 1]]},
        {"type": "plane", "point": [0, -2, 0], "normal": [0, 1, 0]}]})");
    const RasterScene rs = tessellate_scene(scene);
    ASSERT_GT(rs.triangles.size(), 4u);
    for (size_t k = 1; k < rs.triangles.size(); ++k)
        EXPECT_LE(rs.triangles.id[k - 1], rs.triangles.id[k]);
    EXPECT_EQ(rs.triangles.id.front(), 0u);
    EXPECT_EQ(rs.triangles.id.back(), 3u);
}

}  // namespace
}  // namespace hikari
