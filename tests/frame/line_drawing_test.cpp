#include "hikari/frame/line_drawing.h"

#include <gtest/gtest.h>

#include "hikari/frame/depth_cue.h"

namespace hikari {
namespace {

TEST(LineDrawing, WorldPointIsPerspectiveCorrect) {
    LineSegment s;
    s.a = {0, 0};
    s.b = {10, 0};
    s.world_a = Vec3(0, 0, -1);
    s.world_b = Vec3(0, 0, -3);
    s.inv_w_a = 1.0f;
    s.inv_w_b = 1.0f / 3.0f;
    // Halfway on screen, 1/w is halfway between 1 and 1/3: w = 1.5.
    EXPECT_NEAR(segment_world_point(s, 0.5f).z, -1.5f, 1e-6f);
    const LineSegment half = sub_segment(s, 0.5f, 1.0f);
    EXPECT_NEAR(half.a.x, 5.0f, 1e-6f);
    EXPECT_NEAR(half.world_a.z, -1.5f, 1e-6f);
    EXPECT_NEAR(half.inv_w_a, 2.0f / 3.0f, 1e-6f);
}

TEST(LineDrawing, DepthCueSplitsSegmentsAndBlendsEachPiece) {
    LineDrawing d;
    d.width = d.height = 100;
    d.camera.eye = Vec3(0.0f);
    d.background = Vec3(0.0f, 0.0f, 1.0f);
    LineSegment s;
    s.a = {0, 50};
    s.b = {100, 50};
    s.world_a = Vec3(0, 0, -2);
    s.world_b = Vec3(0, 0, -12);
    s.inv_w_a = 0.5f;
    s.inv_w_b = 1.0f / 12.0f;
    s.color = Vec3(1.0f, 1.0f, 0.0f);
    d.segments.push_back(s);
    DepthCue cue;
    cue.near = 2.0f;
    cue.far = 12.0f;
    const LineDrawing cued = depth_cued(d, cue);
    EXPECT_EQ(cued.background, d.background);  // the cue colour defaults to the background
    ASSERT_GE(cued.segments.size(), 128u);
    float covered = 0;
    for (const LineSegment& p : cued.segments) {
        covered += segment_length(p);
        const float w0 = depth_cue_weight(cue, length(p.world_a));
        const float w1 = depth_cue_weight(cue, length(p.world_b));
        EXPECT_LE(std::abs(w1 - w0), 1.0f / 64.0f);
        // Its colour is the cue's blend at some point of the piece.
        const float w = p.color.x;
        EXPECT_GE(w, std::min(w0, w1) - 1e-5f);
        EXPECT_LE(w, std::max(w0, w1) + 1e-5f);
        EXPECT_NEAR(p.color.z, 1.0f - w, 1e-5f);
    }
    EXPECT_NEAR(covered, 100.0f, 1e-3f);
}

}  // namespace
}  // namespace hikari
