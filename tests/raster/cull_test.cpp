#include "hikari/raster/cull.h"

#include <gtest/gtest.h>

#include "hikari/raster/zbuffer.h"
#include "raster_test_util.h"

namespace hikari {
namespace {

TEST(Cull, CounterClockwiseTowardTheEyeIsFront) {
    const Vec3 eye{0, 0, 5};
    // Seen from +z these run counter-clockwise: N = (P2 − P1) × (P3 − P2) = +z, toward the eye.
    const Vec3 p1{0, 0, 0}, p2{1, 0, 0}, p3{0, 1, 0};
    EXPECT_GT(face_normal(p1, p2, p3).z, 0.0f);
    EXPECT_FALSE(is_back_face(p1, p2, p3, eye));
    EXPECT_TRUE(is_back_face(p1, p3, p2, eye));
    EXPECT_TRUE(is_back_face(p1, p2, p3, Vec3{0, 0, -5}));  // seen from behind
}

TEST(Cull, BackFacingTriangleDisappearsOnlyWhenCulling) {
    auto scene_with = [](const char* vertices) {
        return testing::raster_scene_from(
            std::string(R"({"camera": {"eye": [0, 0, 3], "look_at": [0, 0, 0], "width": 32,
              "height": 32}, "objects": [{"type": "triangle", "vertices": )") +
            vertices + "}]}");
    };
    const Scene front = scene_with("[[-1, -1, 0], [1, -1, 0], [0, 1, 0]]");
    const Scene back = scene_with("[[-1, -1, 0], [0, 1, 0], [1, -1, 0]]");
    RasterSettings cull;
    cull.cull_back_faces = true;
    auto covered = [](const Framebuffer& fb) {
        size_t n = 0;
        for (uint32_t id : fb.id) n += id != 0;
        return n;
    };
    EXPECT_GT(covered(render_zbuffer(front, Film(front.camera), {}, cull)), 100u);
    EXPECT_EQ(covered(render_zbuffer(back, Film(back.camera), {}, cull)), 0u);
    EXPECT_EQ(covered(render_zbuffer(back, Film(back.camera))),
              covered(render_zbuffer(front, Film(front.camera))));
}

}  // namespace
}  // namespace hikari
