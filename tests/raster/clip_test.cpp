#include "hikari/raster/clip.h"

#include <gtest/gtest.h>

#include "hikari/integrators/whitted/whitted.h"
#include "hikari/raster/vertex_pipeline.h"
#include "hikari/raster/zbuffer.h"
#include "raster_test_util.h"

namespace hikari {
namespace {

// Clip-space points with w = view depth; the near plane is z = −w.
Vec4 at_depth(float x, float y, float depth) { return {x, y, depth - 2.0f, depth}; }

void expect_inside_near(const ClipPolygon& p) {
    for (int i = 0; i < p.count; ++i) EXPECT_GE(p.v[i].z + p.v[i].w, -1e-5f);
}

TEST(Clip, TriangleInFrontIsUnchanged) {
    const Vec4 a = at_depth(0, 0, 3), b = at_depth(1, 0, 3), c = at_depth(0, 1, 4);
    const ClipPolygon p = clip_triangle(a, b, c);
    ASSERT_EQ(p.count, 3);
    EXPECT_EQ(p.v[0], a);
    EXPECT_EQ(p.v[1], b);
    EXPECT_EQ(p.v[2], c);
}

TEST(Clip, OneVertexBehindGivesQuad) {
    const ClipPolygon p = clip_triangle(at_depth(0, 0, 3), at_depth(1, 0, 3), at_depth(0, 1, -2));
    EXPECT_EQ(p.count, 4);
    expect_inside_near(p);
}

TEST(Clip, TwoVerticesBehindGivesTriangle) {
    const ClipPolygon p = clip_triangle(at_depth(0, 0, 3), at_depth(1, 0, -1), at_depth(0, 1, -2));
    EXPECT_EQ(p.count, 3);
    expect_inside_near(p);
}

TEST(Clip, TriangleBehindIsDropped) {
    EXPECT_EQ(clip_triangle(at_depth(0, 0, -3), at_depth(1, 0, -1), at_depth(0, 1, 0.5f)).count, 0);
}

TEST(Clip, SharedEdgeIsCutAtTheSamePoint) {
    const Vec4 front = at_depth(0.3f, 0.1f, 5), back = at_depth(-0.2f, 0.4f, -3);
    const ClipPolygon p = clip_triangle(front, back, at_depth(1, 1, 4));
    const ClipPolygon q = clip_triangle(back, front, at_depth(-1, -1, 4));
    auto has = [](const ClipPolygon& poly, Vec4 v) {
        for (int i = 0; i < poly.count; ++i)
            if (poly.v[i] == v) return true;
        return false;
    };
    // p runs front, cut(front, back), …: the cut must appear bit for bit in q too.
    ASSERT_EQ(p.v[0], front);
    EXPECT_TRUE(has(q, p.v[1]));
}

TEST(Clip, GuardBandKeepsScreenCoordinatesBounded) {
    const ClipPolygon p = clip_triangle({-1e6f, 0, 1, 3}, {1e6f, 0, 1, 3}, {0, 1e6f, 1, 3});
    ASSERT_GE(p.count, 3);
    for (int i = 0; i < p.count; ++i) {
        EXPECT_LE(std::abs(p.v[i].x), k_guard_band * p.v[i].w * 1.0001f);
        EXPECT_LE(std::abs(p.v[i].y), k_guard_band * p.v[i].w * 1.0001f);
    }
}

TEST(Clip, GroundPlaneUnderAndBehindCameraMatchesRayTracer) {
    // A floor running under the camera and behind it, plus a sphere: near-plane clipping must
    // neither drop the floor nor smear it across the sky.
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0, 1, 4], "look_at": [0, 0.6, 0], "fov_y": 60, "width": 128, "height": 96},
      "background": [0.3, 0.5, 0.8], "ambient": [0.2, 0.2, 0.2],
      "materials": {"floor": {"ka": [1, 1, 1], "kd": [0.6, 0.6, 0.6]}},
      "lights": [{"type": "directional", "direction": [0, -1, 0], "intensity": [1, 1, 1]}],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"}]})");
    const Framebuffer ray = render_whitted(scene, Film(scene.camera));
    const Framebuffer z = render_zbuffer(scene, Film(scene.camera));
    EXPECT_GE(testing::id_agreement(ray, z), 0.998);
    EXPECT_GE(testing::psnr(ray, z), 40.0);
}

}  // namespace
}  // namespace hikari
