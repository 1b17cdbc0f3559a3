#include "hikari/raster/lines/wireframe.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "../../io/temp_dir.h"
#include "../raster_test_util.h"
#include "hikari/core/color.h"
#include "line_test_util.h"

namespace hikari {
namespace {

std::string box_scene(const testing::TempDir& dir, const std::string& camera) {
    testing::write_text(dir / "box.obj", testing::box_obj({-1, -1, -1}, {1, 1, 1}));
    return R"({"camera": )" + camera + R"(, "objects": [{"type": "mesh", "file": ")" +
           (dir / "box.obj").string() + R"("}]})";
}

const char* k_box_camera =
    R"({"eye": [3, 2.5, 4], "look_at": [0, 0, 0], "fov_y": 50, "width": 200, "height": 160})";

TEST(Wireframe, EachEdgeOnceAndNoQuadDiagonal) {
    testing::TempDir dir;
    const Scene scene = testing::raster_scene_from(box_scene(dir, k_box_camera));
    const LineDrawing d = draw_wireframe(scene, {});
    // A box of six quads: twelve edges, each drawn once, none of the fans' diagonals.
    ASSERT_EQ(d.segments.size(), 12u);
    std::vector<testing::BoxEdge> expected = testing::box_edges({-1, -1, -1}, {1, 1, 1});
    for (const testing::BoxEdge& e : expected) {
        const Vec2 p = testing::pixel_of(scene.camera, e.p),
                   q = testing::pixel_of(scene.camera, e.q);
        int matches = 0;
        for (const LineSegment& s : d.segments)
            matches += (testing::pixel_distance(s.a, p) < 1e-2f &&
                        testing::pixel_distance(s.b, q) < 1e-2f) ||
                       (testing::pixel_distance(s.a, q) < 1e-2f &&
                        testing::pixel_distance(s.b, p) < 1e-2f);
        EXPECT_EQ(matches, 1);
    }
}

TEST(Wireframe, CullingDropsEdgesOfBackFacesOnly) {
    testing::TempDir dir;
    const Scene scene = testing::raster_scene_from(box_scene(dir, k_box_camera));
    LineSettings cull;
    cull.cull_back_faces = true;
    // Seen from a corner, three faces face the eye: their nine edges remain.
    EXPECT_EQ(draw_wireframe(scene, cull).segments.size(), 9u);
}

TEST(Wireframe, SphereShowsItsLatitudeLongitudeGrid) {
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0, 0, 30], "look_at": [0, 0, 0], "width": 64, "height": 64},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]})");
    const LineDrawing d = draw_wireframe(scene, {});
    // Small on screen: 16 meridians of 8 bands and 7 rings of 16 segments, no cell diagonals.
    EXPECT_EQ(d.segments.size(), 16u * 8u + 7u * 16u);
}

TEST(Wireframe, RasterizedLinesCarryColourDepthAndId) {
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0, 0, 0], "look_at": [0, 0, -1], "fov_y": 90, "width": 40,
                 "height": 40},
      "materials": {"red": {"kd": [1, 0, 0]}},
      "objects": [{"type": "triangle", "material": "red",
                   "vertices": [[-1, -1, -2], [1, -1, -2], [0, 1, -2]]}]})");
    RenderSettings settings;
    const Framebuffer fb = render_wireframe(scene, Film(scene.camera), settings, {});
    // The bottom edge runs along y = −1 at depth 2: pixel row 30 (centre 30.5 vs. line 30.0
    // gives half coverage on rows 29 and 30).
    const size_t i = 30 * 40 + 20;
    // Half covered, composited in sRGB (as SVG renderers do): half of red's encoded value.
    EXPECT_NEAR(fb.film.linear().pixels[i].x, srgb_to_linear(0.5f), 1e-5f);
    EXPECT_NEAR(fb.film.linear().pixels[i].y, 0.0f, 1e-5f);
    EXPECT_NEAR(fb.depth[i], std::sqrt(4.0f + 1.0f), 1e-3f);  // the point (0, −1, −2)
    EXPECT_EQ(fb.id[i], 1u);
    EXPECT_EQ(fb.id[0], k_background_id);
}

TEST(Wireframe, SameBytesOnOneThreadAsOnAll) {
    // the edges are found, sorted and rasterized in parallel (bands of rows, each taking its
    // segments in drawing order): the image does not depend on the thread count
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0, 1, 4], "look_at": [0, 0, 0], "width": 150, "height": 110},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1},
                  {"type": "sphere", "center": [0.8, 0, 0.3], "radius": 0.6}]})");
    auto render = [&] {
        return render_wireframe(scene, Film(150, 110, FilmFormat::linear), {}, {}).film.linear();
    };
    Image one;
    {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = render();
    }
    const Image all = render();
    ASSERT_EQ(one.pixels.size(), all.pixels.size());
    size_t drawn = 0;
    for (size_t i = 0; i < one.pixels.size(); ++i) {
        EXPECT_EQ(one.pixels[i], all.pixels[i]) << i;
        drawn += all.pixels[i] != all.pixels[0];
    }
    EXPECT_GT(drawn, 500u);
}

}  // namespace
}  // namespace hikari
