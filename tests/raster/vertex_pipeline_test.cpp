#include "hikari/raster/vertex_pipeline.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "raster_test_util.h"

namespace hikari {
namespace {

const char* k_two_triangles = R"({
  "camera": {"eye": [0, 0, 0], "look_at": [0, 0, -1], "fov_y": 90, "width": 100, "height": 100},
  "objects": [
    {"type": "triangle", "vertices": [[-1, -1, -2], [1, -1, -2], [0, 1, -2]]},
    {"type": "triangle", "vertices": [[-1, -0.5, -3], [1, -0.5, -3], [0, -0.5, 3]]}]})";

TEST(VertexPipeline, ProjectsOntoPixelsWithYDown) {
    const ProjectedScene ps = project_scene(testing::raster_scene_from(k_two_triangles), {});
    ASSERT_GE(ps.triangles.size(), 2u);
    const ScreenTriangle& t = ps.triangles[0];
    EXPECT_EQ(t.source, 0u);
    // fov 90°: x = ±1 at depth 2 maps to ±0.5 NDC → pixels 25 and 75; y = +1 is up (row 25).
    EXPECT_NEAR(t.v[0].position.x, 25.0f, 1e-3f);
    EXPECT_NEAR(t.v[0].position.y, 75.0f, 1e-3f);
    EXPECT_NEAR(t.v[2].position.x, 50.0f, 1e-3f);
    EXPECT_NEAR(t.v[2].position.y, 25.0f, 1e-3f);
    EXPECT_NEAR(t.v[0].inv_w, 0.5f, 1e-6f);
    for (const ScreenVertex& v : t.v) {
        // the depth key −near/w: in [−1, 0), equal to −near · inv_w
        EXPECT_LT(v.position.z, 0.0f);
        EXPECT_GE(v.position.z, -1.0f);
        EXPECT_NEAR(v.position.z, -ps.view.near_plane * v.inv_w, 1e-6f);
    }
}

TEST(VertexPipeline, TriangleThroughTheEyePlaneIsClippedNotDropped) {
    const ProjectedScene ps = project_scene(testing::raster_scene_from(k_two_triangles), {});
    size_t pieces = 0;
    for (const ScreenTriangle& t : ps.triangles)
        if (t.source == 1) {
            ++pieces;
            for (const ScreenVertex& v : t.v) {
                EXPECT_GT(v.inv_w, 0.0f);
                // clipped at the near plane: no point nearer than it (z >= −1)
                EXPECT_GE(v.position.z, -1.0f - 1e-5f);
                EXPECT_TRUE(std::isfinite(v.position.x) && std::isfinite(v.position.y));
            }
        }
    EXPECT_GE(pieces, 1u);
}

TEST(VertexPipeline, OutputDoesNotDependOnThreadCount) {
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0, 1, 3], "look_at": [0, 0, 0], "width": 64, "height": 64},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1},
                  {"type": "plane", "point": [0, -1, 0], "normal": [0, 1, 0]}]})");
    ProjectedScene one;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = project_scene(scene, {});
    }
    const ProjectedScene many = project_scene(scene, {});
    ASSERT_EQ(one.triangles.size(), many.triangles.size());
    for (size_t i = 0; i < one.triangles.size(); ++i) {
        EXPECT_EQ(one.triangles[i].source, many.triangles[i].source);
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(one.triangles[i].v[k].position, many.triangles[i].v[k].position);
    }
}

}  // namespace
}  // namespace hikari
