// hikari explain: what the observers report agrees with an independent run of each algorithm's
// step on a small scene.

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "../io/scene_test_util.h"
#include "hikari/explain/explain.h"
#include "hikari/raster/scanline.h"
#include "hikari/raster/vertex_pipeline.h"
#include "hikari/raster/zbuffer.h"

namespace hikari {
namespace {

// Three overlapping triangles at different depths, one of them tilted, and a sphere.
const std::string k_triangles_and_sphere = R"({
  "camera": {"eye": [0, 0, 6], "look_at": [0, 0, 0], "fov_y": 45, "width": 40, "height": 30},
  "lights": [{"type": "directional", "direction": [0, 0, -1], "intensity": 1}],
  "objects": [
    {"type": "triangle", "vertices": [[-2, -1.5, -1], [2, -1.5, -1], [0, 1.8, -1]]},
    {"type": "triangle", "vertices": [[-1.5, -1, 0.5], [1.8, -0.2, -0.5], [-0.5, 1.5, 0]]},
    {"type": "triangle", "vertices": [[-0.3, -1.2, 1], [1.5, -1, 1], [0.5, 0.6, 1]]},
    {"type": "sphere", "center": [1.2, 0.8, -0.5], "radius": 0.6}
  ]
})";

/// Whether the pixel centre (px, py) is inside screen triangle t (either winding; edges count
/// as inside, which the test avoids by choosing centres well inside).
bool covers(const ScreenTriangle& t, double px, double py) {
    double s[3];
    for (int k = 0; k < 3; ++k) {
        const Vec3 a = t.v[k].position, b = t.v[(k + 1) % 3].position;
        s[k] = (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
    }
    return (s[0] >= 0 && s[1] >= 0 && s[2] >= 0) || (s[0] <= 0 && s[1] <= 0 && s[2] <= 0);
}

TEST(ExplainZBuffer, FragmentsAreTheTrianglesCoveringThePixelInDrawingOrder) {
    const Scene scene = testing::parse(k_triangles_and_sphere);
    const ProjectedScene ps = project_scene(scene, RasterSettings{});
    for (const auto& [x, y] : {std::pair{20, 15}, std::pair{24, 12}, std::pair{5, 25}}) {
        std::vector<ZBufferFragment> fragments;
        const VisibilityBuffer vis = zbuffer_visibility_at(ps.triangles, 40, 30, x, y, fragments);
        EXPECT_EQ(vis.triangle, zbuffer_visibility(ps.triangles, 40, 30).triangle);
        std::vector<uint32_t> expected;
        for (uint32_t t = 0; t < ps.triangles.size(); ++t)
            if (covers(ps.triangles[t], x + 0.5, y + 0.5)) expected.push_back(t);
        std::vector<uint32_t> got;
        float nearest = k_infinity;
        uint32_t winner = k_no_triangle;
        for (const ZBufferFragment& f : fragments) {
            got.push_back(f.triangle);
            EXPECT_EQ(f.stored, nearest);
            EXPECT_EQ(f.won, f.depth < nearest);
            if (f.won) nearest = f.depth, winner = f.triangle;
        }
        EXPECT_EQ(got, expected) << x << "," << y;
        EXPECT_EQ(winner, vis.triangle[static_cast<size_t>(y) * 40 + x]);
    }
}

TEST(ExplainScanline, ActiveEdgesAreTheEdgesCrossingTheScanLine) {
    const Scene scene = testing::parse(k_triangles_and_sphere);
    const ProjectedScene ps = project_scene(scene, RasterSettings{});
    for (const int row : {3, 12, 15, 22}) {
        ScanlineRowTrace trace;
        const VisibilityBuffer vis = scanline_visibility_at(ps.triangles, 40, 30, row, trace);
        EXPECT_EQ(vis.triangle, scanline_visibility(ps.triangles, 40, 30).triangle);
        // Independently: every non-horizontal edge whose y range holds y = row + 0.5, at its x.
        const double y = row + 0.5;
        std::vector<std::pair<double, uint32_t>> expected;
        for (uint32_t t = 0; t < ps.triangles.size(); ++t)
            for (int k = 0; k < 3; ++k) {
                Vec3 a = ps.triangles[t].v[k].position, b = ps.triangles[t].v[(k + 1) % 3].position;
                if (a.y > b.y) std::swap(a, b);
                if (!(a.y < y && y <= b.y) && !(a.y <= y && y < b.y)) continue;
                expected.emplace_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y), t);
            }
        std::sort(expected.begin(), expected.end());
        ASSERT_EQ(trace.active.size(), expected.size()) << row;
        for (size_t i = 0; i < expected.size(); ++i) {
            EXPECT_NEAR(trace.active[i].x, expected[i].first, 1e-6) << row;
        }
        // The spans tile the row's visible pixels exactly as the visibility buffer shows them.
        for (const ScanlineRowTrace::Span& s : trace.spans)
            for (int x = s.first; x < s.end; ++x)
                EXPECT_EQ(vis.triangle[static_cast<size_t>(row) * 40 + x], s.triangle);
        size_t covered = 0;
        for (int x = 0; x < 40; ++x)
            covered += vis.triangle[static_cast<size_t>(row) * 40 + x] != k_no_triangle;
        size_t spanned = 0;
        for (const ScanlineRowTrace::Span& s : trace.spans) spanned += s.end - s.first;
        EXPECT_EQ(spanned, covered) << row;
    }
}

TEST(Explain, TextNamesTheStepsAndRefusesPointsOutsideTheImage) {
    const Scene scene = testing::parse(k_triangles_and_sphere);
    const std::string z = explain_zbuffer_pixel(scene, RasterSettings{}, 20, 15);
    EXPECT_NE(z.find("Z-buffer (Alg 4.2) at pixel (20, 15)"), std::string::npos);
    EXPECT_NE(z.find("written"), std::string::npos);
    const std::string s = explain_scanline_row(scene, RasterSettings{}, 15);
    EXPECT_NE(s.find("Active edge list at y = 15.5"), std::string::npos);
    EXPECT_THROW(explain_zbuffer_pixel(scene, RasterSettings{}, 40, 0), InputError);
    EXPECT_THROW(explain_scanline_row(scene, RasterSettings{}, 30), InputError);
    const std::string m = explain_matrices(scene, RasterSettings{});
    EXPECT_NE(m.find("p_s = V P M p_w"), std::string::npos);
    EXPECT_NE(m.find("sphere (primitive 3)"), std::string::npos);
}

TEST(Explain, ZBufferDescribesTheExactSphereTheRenderDraws) {
    // Phong interpolation (the default) draws spheres exactly, and the explanation follows the
    // render: where the sphere is visible its fragment is the exact sphere's, and no triangle of
    // a tessellated sphere is listed anywhere. Gouraud draws (and explains) its polygons.
    const Scene scene = testing::parse(k_triangles_and_sphere);
    const RasterSettings phong;
    int sphere_pixels = 0;
    for (int y = 0; y < scene.camera.height; ++y)
        for (int x = 0; x < scene.camera.width; ++x) {
            const std::string z = explain_zbuffer_pixel(scene, phong, x, y);
            EXPECT_EQ(z.find("of sphere"), std::string::npos) << z;
            sphere_pixels +=
                z.find("Result: exact sphere (primitive 3) is visible") != std::string::npos;
        }
    EXPECT_GT(sphere_pixels, 20);
    RasterSettings gouraud;
    gouraud.interp = Interpolation::gouraud;
    bool polygons = false;
    for (int x = 0; x < scene.camera.width; ++x) {
        const std::string z = explain_zbuffer_pixel(scene, gouraud, x, 8);
        EXPECT_EQ(z.find("exact"), std::string::npos) << z;
        polygons = polygons || z.find("of sphere") != std::string::npos;
    }
    EXPECT_TRUE(polygons);
}

}  // namespace
}  // namespace hikari

namespace hikari {
namespace {

TEST(ExplainDepthSort, EveryListIsCutAfterMaxStepsAndSaysSo) {
    const Scene scene = testing::parse(k_triangles_and_sphere);
    const std::string whole = explain_depth_sort(scene, RasterSettings{}, 100000);
    EXPECT_EQ(whole.find("not shown"), std::string::npos);
    // The sphere is tessellated into many polygons: two lines of each list are far too few.
    const std::string cut = explain_depth_sort(scene, RasterSettings{}, 2);
    size_t notes = 0;
    for (size_t at = cut.find("not shown"); at != std::string::npos;
         at = cut.find("not shown", at + 1))
        ++notes;
    EXPECT_EQ(notes, 3u);  // the depth list, the steps and the painting order
    EXPECT_LT(cut.size(), whole.size() / 4);
    EXPECT_NE(cut.find("3. Painting order"), std::string::npos);
}

}  // namespace
}  // namespace hikari
