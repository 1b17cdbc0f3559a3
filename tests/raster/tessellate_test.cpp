#include "hikari/raster/tessellate.h"

#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include <gtest/gtest.h>

#include "hikari/core/aabb.h"
#include "hikari/raster/cull.h"
#include "raster_test_util.h"

namespace hikari {
namespace {

TEST(Tessellate, SphereIsClosedAndWoundOutward) {
    TriangleSet t;
    const Sphere s{{1, 2, 3}, 2.0f, 0, 7};
    tessellate_sphere(s, 24, t);
    std::map<std::pair<uint32_t, uint32_t>, int> edges;  // directed edge → count
    for (size_t k = 0; k < t.size(); ++k) {
        const auto& i = t.indices[k];
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
    for (size_t v = 0; v < t.positions.size(); ++v)
        EXPECT_NEAR(length(t.positions[v] - s.center), 2.0f, 1e-5f);
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
