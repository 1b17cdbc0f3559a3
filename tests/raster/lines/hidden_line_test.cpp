#include "hikari/raster/lines/hidden_line.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <numbers>

#include "../../io/temp_dir.h"
#include "../raster_test_util.h"
#include "hikari/raster/cull.h"
#include "line_test_util.h"

namespace hikari {
namespace {

using testing::BoxEdge;
using testing::pixel_of;

std::string mesh_object(const std::filesystem::path& obj) {
    return R"({"type": "mesh", "file": ")" + obj.string() + R"("})";
}

/// Whether the segment from the eye to `p` passes through the inside of the box [lo, hi]
/// before reaching p (slab test; an independent visibility check for points on other boxes).
bool box_hides(Vec3 eye, Vec3 p, Vec3 lo, Vec3 hi) {
    float t0 = 0.0f, t1 = 1.0f - 1e-4f;
    for (int a = 0; a < 3; ++a) {
        const float d = p[a] - eye[a];
        if (std::abs(d) < 1e-12f) {
            if (eye[a] <= lo[a] || eye[a] >= hi[a]) return false;
            continue;
        }
        float ta = (lo[a] - eye[a]) / d, tb = (hi[a] - eye[a]) / d;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    return t1 - t0 > 1e-4f;
}

/// The visible length in pixels of the boxes' edges, by sampling each edge finely and testing
/// every sample against every box (the independent reference).
double sampled_visible_length(const Camera& camera, const std::vector<std::pair<Vec3, Vec3>>& boxes,
                              bool front_face_rule) {
    double total = 0;
    for (const auto& [lo, hi] : boxes)
        for (const BoxEdge& e : testing::box_edges(lo, hi)) {
            // A box's own edge is visible from outside only where one of its two faces faces
            // the eye (a convex body hides its back).
            const Vec3 mid = 0.5f * (e.p + e.q);
            bool front = false;
            for (int a = 0; a < 3; ++a) {
                if (a == e.axis) continue;
                const bool at_hi = mid[a] == hi[a];
                const float outward = at_hi ? 1.0f : -1.0f;
                front |= outward * (camera.eye[a] - mid[a]) > 0.0f;
            }
            if (front_face_rule && !front) continue;
            constexpr int n = 4000;
            for (int k = 0; k < n; ++k) {
                const Vec3 p0 = e.p + (e.q - e.p) * (float(k) / n);
                const Vec3 p1 = e.p + (e.q - e.p) * (float(k + 1) / n);
                const Vec3 m = 0.5f * (p0 + p1);
                bool hidden = false;
                for (const auto& [olo, ohi] : boxes)
                    hidden |= (olo != lo || ohi != hi) && box_hides(camera.eye, m, olo, ohi);
                if (!hidden)
                    total += testing::pixel_distance(pixel_of(camera, p0), pixel_of(camera, p1));
            }
        }
    return total;
}

TEST(HiddenLine, ConvexBoxShowsExactlyTheEdgesOfItsFrontFaces) {
    testing::TempDir dir;
    testing::write_text(dir / "box.obj", testing::box_obj({-1, -1, -1}, {1, 1, 1}));
    for (const char* eye : {"[3, 2.5, 4]", "[-4, 1.6, 2]", "[0.5, -3, 3]"}) {
        SCOPED_TRACE(eye);
        const Scene scene = testing::raster_scene_from(
            std::string(R"({"camera": {"eye": )") + eye +
            R"(, "look_at": [0, 0, 0], "fov_y": 50, "width": 320, "height": 240},
               "objects": [)" +
            mesh_object(dir / "box.obj") + "]}");
        const std::vector<std::pair<Vec3, Vec3>> boxes = {{{-1, -1, -1}, {1, 1, 1}}};
        const double want = sampled_visible_length(scene.camera, boxes, true);
        for (const bool cull : {false, true}) {
            LineSettings lines;
            lines.cull_back_faces = cull;
            const LineDrawing d = draw_hidden_lines(scene, lines);
            EXPECT_NEAR(testing::total_length(d), want, 0.01 * want) << "cull " << cull;
        }
    }
}

TEST(HiddenLine, BoxBehindABoxLosesWhatTheFrontOneCovers) {
    testing::TempDir dir;
    const Vec3 lo_a{-1, -1, -1}, hi_a{1, 1, 1}, lo_b{0.2f, -0.5f, -4}, hi_b{2.5f, 1.5f, -2};
    testing::write_text(dir / "a.obj", testing::box_obj(lo_a, hi_a));
    testing::write_text(dir / "b.obj", testing::box_obj(lo_b, hi_b));
    const Scene scene = testing::raster_scene_from(
        R"({"camera": {"eye": [1.5, 1.8, 5], "look_at": [0.5, 0, -1], "fov_y": 55,
                       "width": 320, "height": 240},
            "objects": [)" +
        mesh_object(dir / "a.obj") + ", " + mesh_object(dir / "b.obj") + "]}");
    const std::vector<std::pair<Vec3, Vec3>> boxes = {{lo_a, hi_a}, {lo_b, hi_b}};
    const LineDrawing d = draw_hidden_lines(scene, {});
    const double want = sampled_visible_length(scene.camera, boxes, true);
    EXPECT_NEAR(testing::total_length(d), want, 0.01 * want);
    // Nothing is drawn where the reference finds it hidden: every drawn point is visible.
    for (const LineSegment& s : d.segments)
        for (const float t : {0.1f, 0.5f, 0.9f}) {
            const Vec3 p = segment_world_point(s, t);
            EXPECT_FALSE(box_hides(scene.camera.eye, p, lo_a, hi_a) ||
                         box_hides(scene.camera.eye, p, lo_b, hi_b))
                << "hidden point drawn at " << p.x << ", " << p.y << ", " << p.z;
        }
}

TEST(HiddenLine, ATinyImageHidesAsALargeOneDoes) {
    // Occluders are looked for within a grid cell of each line where cells are under a pixel
    // (a whole pixel around every line of a 1x1 image made every line meet every face: the
    // bunny took 85 s). The drawing of a 4x3 image is the 320x240 one, 80 times smaller.
    testing::TempDir dir;
    const Vec3 lo_a{-1, -1, -1}, hi_a{1, 1, 1}, lo_b{0.2f, -0.5f, -4}, hi_b{2.5f, 1.5f, -2};
    testing::write_text(dir / "a.obj", testing::box_obj(lo_a, hi_a));
    testing::write_text(dir / "b.obj", testing::box_obj(lo_b, hi_b));
    const auto scene_of = [&](int width, int height) {
        return testing::raster_scene_from(
            R"({"camera": {"eye": [1.5, 1.8, 5], "look_at": [0.5, 0, -1], "fov_y": 55,
                           "width": )" +
            std::to_string(width) + R"(, "height": )" + std::to_string(height) + R"(},
                "objects": [)" +
            mesh_object(dir / "a.obj") + ", " + mesh_object(dir / "b.obj") + "]}");
    };
    const std::vector<std::pair<Vec3, Vec3>> boxes = {{lo_a, hi_a}, {lo_b, hi_b}};
    const double want = sampled_visible_length(scene_of(320, 240).camera, boxes, true) / 80.0;
    const LineDrawing tiny = draw_hidden_lines(scene_of(4, 3), {});
    EXPECT_NEAR(testing::total_length(tiny), want, 0.01 * want);
}

TEST(HiddenLine, InterpenetratingBoxesAgreeWithRayCastingFromSeveralViewpoints) {
    // Two boxes that pierce each other: a non-convex union with intersection lines. Reference:
    // a point is visible when the segment from the eye to it passes through neither box's
    // inside (a box is convex, so the slab test is exact).
    testing::TempDir dir;
    const Vec3 lo_a{-1, -1, -1}, hi_a{1, 1, 1}, lo_b{0.3f, -0.4f, -0.5f}, hi_b{1.8f, 0.6f, 1.6f};
    testing::write_text(dir / "a.obj", testing::box_obj(lo_a, hi_a));
    testing::write_text(dir / "b.obj", testing::box_obj(lo_b, hi_b));
    auto visible = [&](Vec3 eye, Vec3 p) {
        return !box_hides(eye, p, lo_a, hi_a) && !box_hides(eye, p, lo_b, hi_b);
    };
    for (const char* eye : {"[3, 2.5, 4]", "[-2.5, 1.7, 4.2]", "[4.5, -1.2, 0.8]"}) {
        SCOPED_TRACE(eye);
        const Scene scene = testing::raster_scene_from(
            std::string(R"({"camera": {"eye": )") + eye +
            R"(, "look_at": [0.3, 0, 0.2], "fov_y": 55, "width": 320, "height": 240},
               "objects": [)" +
            mesh_object(dir / "a.obj") + ", " + mesh_object(dir / "b.obj") + "]}");
        const LineDrawing d = draw_hidden_lines(scene, {});
        // Nothing hidden is drawn...
        for (const LineSegment& s : d.segments)
            for (const float t : {0.05f, 0.5f, 0.95f})
                EXPECT_TRUE(visible(scene.camera.eye, segment_world_point(s, t)))
                    << "hidden point drawn on a segment " << segment_length(s) << " px long";
        // ...and every visible point of every box edge is drawn.
        int missing = 0, checked = 0;
        for (const auto& [lo, hi] : {std::pair{lo_a, hi_a}, std::pair{lo_b, hi_b}})
            for (const BoxEdge& e : testing::box_edges(lo, hi))
                for (int k = 0; k < 200; ++k) {
                    const Vec3 p = e.p + (e.q - e.p) * ((float(k) + 0.5f) / 200.0f);
                    if (!visible(scene.camera.eye, p)) continue;
                    ++checked;
                    float nearest = INFINITY;
                    for (const LineSegment& s : d.segments)
                        nearest = std::min(nearest, testing::distance_to_segment(
                                                        pixel_of(scene.camera, p), s.a, s.b));
                    missing += nearest > 0.05f;
                }
        EXPECT_GT(checked, 500);
        EXPECT_EQ(missing, 0);
    }
}

TEST(HiddenLine, PiercingTrianglesDrawTheirIntersectionAndHideWhatIsBeyond) {
    // A faces the eye at z = −3; B, edge-on in x = 0, pierces it, reaching from z = −2 (in
    // front) to z = −4 (behind).
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0.8, 0.5, 0], "look_at": [0, 0, -3], "fov_y": 60, "width": 200,
                 "height": 200},
      "objects": [
        {"type": "triangle", "vertices": [[-1.5, -1, -3], [1.5, -1, -3], [0, 1.5, -3]]},
        {"type": "triangle", "vertices": [[0, -0.5, -2], [0, -0.5, -4], [0, 0.5, -3]]}]})");
    const LineDrawing d = draw_hidden_lines(scene, {});
    // The intersection line: x = 0, z = −3, from y = −0.5 to y = 0.5 (B's edges from its
    // corner (0, 0.5, −3)... B meets z = −3 along its corner (0, 0.5, −3) to (0, −0.5, −3)).
    const Vec2 p = pixel_of(scene.camera, {0, -0.5f, -3}),
               q = pixel_of(scene.camera, {0, 0.5f, -3});
    double on_intersection = 0;
    for (const LineSegment& s : d.segments)
        if (testing::distance_to_segment(s.a, p, q) < 0.05f &&
            testing::distance_to_segment(s.b, p, q) < 0.05f)
            on_intersection += segment_length(s);
    EXPECT_NEAR(on_intersection, testing::pixel_distance(p, q), 0.02);
    // B's bottom edge from (0, −0.5, −2) to (0, −0.5, −4) is visible up to where it pierces A
    // (z = −3) and hidden beyond it: the part behind A is not drawn.
    const Vec2 front = pixel_of(scene.camera, {0, -0.5f, -2});
    const Vec2 pierce = pixel_of(scene.camera, {0, -0.5f, -3});
    const Vec2 back = pixel_of(scene.camera, {0, -0.5f, -4});
    double front_part = 0, back_part = 0;
    for (const LineSegment& s : d.segments) {
        if (testing::distance_to_segment(s.a, front, pierce) < 0.05f &&
            testing::distance_to_segment(s.b, front, pierce) < 0.05f)
            front_part += segment_length(s);
        const Vec2 mid = segment_point(s, 0.5f);
        if (testing::distance_to_segment(mid, pierce, back) < 0.05f &&
            testing::pixel_distance(mid, pierce) > 0.5f)
            back_part += segment_length(s);
    }
    EXPECT_NEAR(front_part, testing::pixel_distance(front, pierce), 0.02);
    EXPECT_EQ(back_part, 0.0);
}

TEST(HiddenLine, SphereOutlineIsItsSilhouetteAndNothingBehindIsDrawn) {
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0, 1, 5], "look_at": [0, 0, 0], "fov_y": 40, "width": 200,
                 "height": 200},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]})");
    const LineDrawing d = draw_hidden_lines(scene, {});
    const Vec3 eye = scene.camera.eye;
    // Every drawn point lies on the half the eye sees, up to the tessellation's facets (the
    // silhouette edges zigzag along the grid, at most a cell, some 5 degrees, beyond it).
    size_t behind = 0;
    for (const LineSegment& s : d.segments)
        for (const float t : {0.0f, 0.5f, 1.0f}) {
            const Vec3 p = segment_world_point(s, t);
            EXPECT_GT(dot(p, normalize(eye - p)), -0.09f) << p.x << ", " << p.y << ", " << p.z;
            behind += dot(p, normalize(eye - p)) < 0.0f;
        }
    EXPECT_LT(behind, d.segments.size() / 4);
    // The silhouette: the projected outline of the sphere, a circle of the sphere's angular
    // radius; at every angle a line passes within a pixel of it.
    const Vec2 centre = pixel_of(scene.camera, {0, 0, 0});
    const float dist = length(eye);
    const float tan_half = std::tan(20.0f * std::numbers::pi_v<float> / 180.0f);
    const float radius_px = (1.0f / std::sqrt(dist * dist - 1.0f)) / tan_half * 100.0f;
    for (int k = 0; k < 90; ++k) {
        const float angle = 2.0f * std::numbers::pi_v<float> * float(k) / 90.0f;
        const Vec2 outline{centre.x + radius_px * std::cos(angle),
                           centre.y + radius_px * std::sin(angle)};
        float nearest = INFINITY;
        for (const LineSegment& s : d.segments)
            nearest = std::min(nearest, testing::distance_to_segment(outline, s.a, s.b));
        EXPECT_LT(nearest, 1.0f) << "angle " << angle;
    }
}

TEST(HiddenLine, ResultDoesNotDependOnThreadCount) {
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0, 1, 4], "look_at": [0, 0, 0], "width": 96, "height": 64},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1},
                  {"type": "sphere", "center": [0.8, 0, 0.3], "radius": 0.6},
                  {"type": "plane", "point": [0, -1, 0], "normal": [0, 1, 0]}]})");
    LineDrawing one;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = draw_hidden_lines(scene, {});
    }
    const LineDrawing all = draw_hidden_lines(scene, {});
    ASSERT_EQ(one.segments.size(), all.segments.size());
    for (size_t k = 0; k < one.segments.size(); ++k) {
        EXPECT_EQ(one.segments[k].a.x, all.segments[k].a.x);
        EXPECT_EQ(one.segments[k].b.y, all.segments[k].b.y);
    }
}

TEST(HiddenLine, ATinyImageOfADenseMeshTakesNoMoreWorkThanALargeOne) {
    // The candidate grid follows the projected scene, not the pixels. At 1 × 1, where the model
    // overflows the image, 8-pixel cells (or cells of 1/64 pixel over the image) once put most
    // faces into the border cells, and every line near the border was tested against all of
    // them: minutes for the bunny (past this test's time limit), where 1920 × 1080 takes a
    // fraction of a second. Now both take the same work.
    auto scene_of = [](int size) {
        return testing::raster_scene_from(fmt::format(R"({{
          "camera": {{"eye": [-0.02, 0.11, 0.3], "look_at": [-0.02, 0.11, 0], "fov_y": 20,
                      "width": {0}, "height": {0}}},
          "objects": [{{"type": "mesh", "file": "scenes/models/stanford-bunny.obj"}}]}})",
                                                      size));
    };
    for (const int size : {1, 3, 200}) {
        const LineDrawing d = draw_hidden_lines(scene_of(size), {});
        EXPECT_EQ(d.width, size);
        // every segment lies in the view widened by the line width (1 pixel) it was clipped to
        for (const LineSegment& s : d.segments)
            for (const Vec2 p : {s.a, s.b}) {
                EXPECT_GE(p.x, -1.01f) << size;
                EXPECT_LE(p.x, float(size) + 1.01f) << size;
            }
        if (size == 200) EXPECT_GT(d.segments.size(), 1000u);
    }
}

}  // namespace
}  // namespace hikari
