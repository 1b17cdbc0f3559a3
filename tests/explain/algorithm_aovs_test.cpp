// --aov overdraw | paint-order | spans | culled: the algorithms' own counts, checked against
// their traces and against what a scene must give.

#include <string>

#include <gtest/gtest.h>

#include "../io/scene_test_util.h"
#include "hikari/explain/algorithm_aovs.h"
#include "hikari/raster/depth_sort.h"
#include "hikari/raster/scanline.h"
#include "hikari/raster/vertex_pipeline.h"
#include "hikari/raster/zbuffer.h"

namespace hikari {
namespace {

// Two triangles facing the camera, overlapping, and one wound away from it.
const std::string k_overlapping_triangles = R"({
  "camera": {"eye": [0, 0, 6], "look_at": [0, 0, 0], "fov_y": 45, "width": 40, "height": 30},
  "lights": [{"type": "directional", "direction": [0, 0, -1], "intensity": 1}],
  "objects": [
    {"type": "triangle", "vertices": [[-2, -1.5, -1], [2, -1.5, -1], [0, 1.8, -1]]},
    {"type": "triangle", "vertices": [[-1.5, -1, 0.5], [1.8, -0.2, -0.5], [-0.5, 1.5, 0]]},
    {"type": "triangle", "vertices": [[1.2, 0.5, 1], [1.0, 1.4, 1], [2.2, 0.6, 1]]}
  ]
})";

TEST(AlgorithmAovs, ZBufferOverdrawCountsEveryFragmentTested) {
    const Scene scene = testing::parse(k_overlapping_triangles);
    const ProjectedScene ps = project_scene(scene, RasterSettings{});
    std::vector<uint32_t> count;
    zbuffer_visibility_counted(ps.triangles, 40, 30, count);
    for (const auto& [x, y] : {std::pair{20, 15}, std::pair{5, 25}, std::pair{30, 8}}) {
        std::vector<ZBufferFragment> fragments;
        zbuffer_visibility_at(ps.triangles, 40, 30, x, y, fragments);
        EXPECT_EQ(count[static_cast<size_t>(y) * 40 + x], fragments.size()) << x << "," << y;
    }
    const AlgorithmAov raw =
        algorithm_aov(scene, *find_method("zbuffer"), Aov::overdraw, MethodSettings{}, true);
    EXPECT_EQ(raw.image.at(20, 15).x, static_cast<float>(count[15 * 40 + 20]));
}

TEST(AlgorithmAovs, DepthSortPaintsAndOrderMatchItsVisibility) {
    const Scene scene = testing::parse(k_overlapping_triangles);
    const ProjectedScene ps = project_scene(scene, RasterSettings{});
    DepthSortTrace trace;
    const VisibilityBuffer vis = depth_sort_visibility_traced(ps.triangles, 40, 30, trace);
    EXPECT_EQ(vis.triangle, depth_sort_visibility(ps.triangles, 40, 30).triangle);
    for (size_t i = 0; i < vis.triangle.size(); ++i) {
        if (vis.triangle[i] == k_no_triangle) {
            EXPECT_EQ(trace.paint_count[i], 0u);
            continue;
        }
        ASSERT_NE(trace.visible_paint[i], UINT32_MAX);
        EXPECT_EQ(trace.source[trace.painted[trace.visible_paint[i]]], vis.triangle[i]);
        EXPECT_GE(trace.paint_count[i], 1u);
    }
    const AlgorithmAov order =
        algorithm_aov(scene, *find_method("depthsort"), Aov::paint_order, MethodSettings{}, true);
    EXPECT_EQ(order.image.at(0, 0).x, 0.0f);  // nothing painted in the corner
}

TEST(AlgorithmAovs, SpansMarkTheStartOfEverySpanTheTraceReports) {
    const Scene scene = testing::parse(k_overlapping_triangles);
    const ProjectedScene ps = project_scene(scene, RasterSettings{});
    std::vector<uint8_t> starts;
    scanline_visibility_spans(ps.triangles, 40, 30, starts);
    for (const int row : {5, 12, 20}) {
        ScanlineRowTrace trace;
        scanline_visibility_at(ps.triangles, 40, 30, row, trace);
        size_t marked = 0;
        for (int x = 0; x < 40; ++x) marked += starts[static_cast<size_t>(row) * 40 + x];
        EXPECT_EQ(marked, trace.spans.size()) << row;
        for (const ScanlineRowTrace::Span& s : trace.spans)
            EXPECT_EQ(starts[static_cast<size_t>(row) * 40 + s.first], 1) << row;
    }
}

TEST(AlgorithmAovs, CulledShowsOnlyTheBackFaceThatWouldBeSeen) {
    const Scene scene = testing::parse(k_overlapping_triangles);
    const AlgorithmAov a =
        algorithm_aov(scene, *find_method("zbuffer"), Aov::culled, MethodSettings{}, false);
    EXPECT_NE(a.summary.find("1 of 3 triangles are back faces"), std::string::npos) << a.summary;
    int magenta = 0;
    for (const Vec3& p : a.image.pixels) magenta += p.x - p.y > 0.4f && p.z - p.y > 0.4f;
    EXPECT_GT(magenta, 0);
}

TEST(AlgorithmAovs, EachMethodOffersItsOwn) {
    EXPECT_TRUE(has_algorithm_aov(*find_method("zbuffer"), Aov::overdraw));
    EXPECT_TRUE(has_algorithm_aov(*find_method("depthsort"), Aov::paint_order));
    EXPECT_FALSE(has_algorithm_aov(*find_method("zbuffer"), Aov::paint_order));
    EXPECT_TRUE(has_algorithm_aov(*find_method("scanline"), Aov::spans));
    EXPECT_FALSE(has_algorithm_aov(*find_method("raytrace"), Aov::culled));
    EXPECT_EQ(methods_with_algorithm_aov(Aov::overdraw), "zbuffer, depthsort");
}

}  // namespace
}  // namespace hikari
