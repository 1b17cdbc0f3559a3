#include "hikari/raster/lines/line_clip.h"

#include <gtest/gtest.h>

#include "../raster_test_util.h"
#include "hikari/raster/lines/line_projection.h"

namespace hikari {
namespace {

TEST(LineClip, InsideSegmentIsKeptWhole) {
    const auto r = clip_segment({0, 0, 0, 1}, {0.5f, 0.5f, 0.5f, 2});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->t0, 0.0f);
    EXPECT_EQ(r->t1, 1.0f);
}

TEST(LineClip, SegmentThroughTheNearPlaneIsCutThere) {
    // z + w goes from 2 at a to −2 at b: the near plane z = −w is crossed halfway.
    const Vec4 a{0, 0, 0, 2}, b{0, 0, -1, -1};
    const auto r = clip_segment(a, b);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->t0, 0.0f);
    EXPECT_NEAR(r->t1, 0.5f, 1e-6f);
    // The other way round the start moves.
    const auto back = clip_segment(b, a);
    ASSERT_TRUE(back);
    EXPECT_NEAR(back->t0, 0.5f, 1e-6f);
    EXPECT_EQ(back->t1, 1.0f);
}

TEST(LineClip, SegmentBehindTheEyeOrBesideTheFrustumIsDropped) {
    EXPECT_FALSE(clip_segment({0, 0, 1, -1}, {0, 0, 2, -2}));   // behind the eye
    EXPECT_FALSE(clip_segment({3, 0, 0, 1}, {4, 0.5f, 0, 1}));  // right of x = w
    // ...unless the margin widens the frustum enough.
    EXPECT_TRUE(clip_segment({1.05f, 0, 0, 1}, {1.08f, 0, 0, 1}, 0.1f));
}

TEST(LineClip, EdgeReachingBehindTheEyeIsProjectedNotWrapped) {
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0, 0, 0], "look_at": [0, 0, -1], "fov_y": 90, "width": 100,
                 "height": 100},
      "objects": [{"type": "sphere", "center": [0, 0, -5], "radius": 1}]})");
    const LineScene ls = prepare_line_scene(scene, {});
    // From the view's centre line at depth 4 to a point behind the eye, up and to the right.
    const auto seg = project_segment(ls.projected.view, {0, 0, -4}, {0.4f, 0.4f, 2}, 1.0f);
    ASSERT_TRUE(seg);
    EXPECT_NEAR(seg->a.x, 50.0f, 1e-3f);
    EXPECT_NEAR(seg->a.y, 50.0f, 1e-3f);
    // The visible part runs up and right from the centre (not wrapped to the lower left) and
    // stops at the near plane, in front of the eye.
    EXPECT_GE(seg->b.x, 50.0f);
    EXPECT_LE(seg->b.y, 50.0f);
    EXPECT_GT(seg->inv_w_b, 0.0f);
    EXPECT_LT(seg->world_b.z, 0.0f);
    EXPECT_NEAR(-seg->world_b.z, std::min(ls.projected.view.near_plane, 4.0f), 1e-3f);
}

}  // namespace
}  // namespace hikari
