#include "hikari/raster/lines/line_projection.h"

#include <gtest/gtest.h>

#include "../raster_test_util.h"

namespace hikari {
namespace {

TEST(LineProjection, CullingKeepsEdgesWithAFrontFace) {
    ModelEdge e;
    e.faces = {0, 1};
    const std::vector<uint8_t> back_facing = {1, 0, 1};
    EXPECT_TRUE(edge_has_kept_face(e, back_facing, true));
    e.faces = {0, 2};
    EXPECT_FALSE(edge_has_kept_face(e, back_facing, true));
    EXPECT_TRUE(edge_has_kept_face(e, back_facing, false));
    e.faces = {2, k_no_face};
    EXPECT_FALSE(edge_has_kept_face(e, back_facing, true));
}

TEST(LineProjection, LinesTakeTheMaterialOrTheGivenColour) {
    const Scene scene = testing::raster_scene_from(R"({
      "materials": {"red": {"kd": [0.8, 0.1, 0.05]}},
      "objects": [{"type": "sphere", "center": [0, 0, -3], "radius": 1, "material": "red"}]})");
    const uint32_t red = scene.spheres[0].material;
    EXPECT_EQ(line_color(scene, red, {}), Vec3(0.8f, 0.1f, 0.05f));
    LineSettings blue;
    blue.color = Vec3(0, 0, 1);
    EXPECT_EQ(line_color(scene, red, blue), Vec3(0, 0, 1));
}

TEST(LineProjection, BackFacesAreTheOnesTheEyeSeesFromBehind) {
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0, 0, 0], "look_at": [0, 0, -1]},
      "objects": [{"type": "triangle", "vertices": [[-1, -1, -2], [1, -1, -2], [0, 1, -2]]},
                  {"type": "triangle", "vertices": [[-1, -1, -3], [0, 1, -3], [1, -1, -3]]}]})");
    const LineScene ls = prepare_line_scene(scene, {});
    EXPECT_EQ(ls.back_facing, (std::vector<uint8_t>{0, 1}));
    EXPECT_EQ(ls.edges.size(), 6u);
    LineSettings cull;
    cull.cull_back_faces = true;
    // Culled, the back face is gone from the projected triangles (it hides nothing).
    EXPECT_EQ(prepare_line_scene(scene, cull).projected.triangles.size(), 1u);
}

}  // namespace
}  // namespace hikari
