// AOV buffers as pictures for 8-bit files: depth spans the grey range, ids in false colour,
// normals as 0.5 + 0.5 n.

#include <gtest/gtest.h>

#include "hikari/core/color.h"
#include "hikari/frame/aov_picture.h"

namespace hikari {
namespace {

Framebuffer three_pixels() {
    Framebuffer fb(Film(3, 1, FilmFormat::linear), 3, 1, true);
    fb.depth = {2.0f, 6.0f, k_infinity};
    fb.id = {1, 2, k_background_id};
    fb.normal = {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0.0f)};
    return fb;
}

uint8_t byte_of(float linear) { return linear_to_srgb8(linear); }

TEST(AovPicture, DepthSpansTheGreyRangeNearWhiteFarBlack) {
    const Image p = aov_picture(three_pixels(), Aov::depth, std::nullopt);
    EXPECT_EQ(byte_of(p.pixels[0].x), 255);  // nearest visible point
    EXPECT_EQ(byte_of(p.pixels[1].x), 0);    // farthest
    EXPECT_EQ(byte_of(p.pixels[2].x), 0);    // background
}

TEST(AovPicture, DepthIsRangedToTheObjectsNotToAnInfiniteFloor) {
    // Primitive 0 an object 2 to 4 units away, primitive 1 a floor plane reaching 900 units.
    Framebuffer fb(Film(4, 1, FilmFormat::linear), 4, 1, true);
    fb.depth = {2.0f, 4.0f, 3.0f, 900.0f};
    fb.id = {1, 1, 2, 2};
    const std::vector<PrimitiveId> floor = {1};
    const std::optional<DepthRange> range = visible_depth_range(fb, floor);
    ASSERT_TRUE(range);
    EXPECT_EQ(range->near, 2.0f);
    EXPECT_EQ(range->far, 4.0f);
    const Image p = aov_picture(fb, Aov::depth, std::nullopt, floor);
    EXPECT_EQ(byte_of(p.pixels[0].x), 255);
    EXPECT_EQ(byte_of(p.pixels[2].x), 128);  // the floor beside the object: mid grey
    EXPECT_EQ(byte_of(p.pixels[3].x), 0);    // the floor far off: black, not the scale's end
    // Only the floor in view: its own range.
    fb.id = {2, 2, 2, 2};
    EXPECT_EQ(visible_depth_range(fb, floor)->far, 900.0f);
    // A scene's planes are its unbounded primitives.
    Scene scene;
    scene.planes.push_back(Plane{});
    scene.planes.back().id = 7;
    EXPECT_EQ(unbounded_primitives(scene), std::vector<PrimitiveId>{7});
}

TEST(AovPicture, DepthRangeFixesTheScale) {
    const Image p = aov_picture(three_pixels(), Aov::depth, DepthRange{0.0f, 8.0f});
    EXPECT_EQ(byte_of(p.pixels[0].x), 191);  // 1 − 2/8 = 0.75 of the byte range
    EXPECT_EQ(byte_of(p.pixels[1].x), 64);   // 1 − 6/8
    const Image clamped = aov_picture(three_pixels(), Aov::depth, DepthRange{3.0f, 5.0f});
    EXPECT_EQ(byte_of(clamped.pixels[0].x), 255);
    EXPECT_EQ(byte_of(clamped.pixels[1].x), 0);
}

TEST(AovPicture, IdsInDistinctColoursBackgroundBlack) {
    const Image p = aov_picture(three_pixels(), Aov::id, std::nullopt);
    EXPECT_NE(p.pixels[0], p.pixels[1]);
    EXPECT_GT(p.pixels[0].x + p.pixels[0].y + p.pixels[0].z, 0.3f);
    EXPECT_EQ(p.pixels[2], Vec3(0.0f));
}

TEST(AovPicture, NormalsAsHalfPlusHalfN) {
    const Image p = aov_picture(three_pixels(), Aov::normal, std::nullopt);
    EXPECT_EQ(byte_of(p.pixels[0].x), 128);
    EXPECT_EQ(byte_of(p.pixels[0].z), 255);
    EXPECT_EQ(byte_of(p.pixels[1].x), 255);
    EXPECT_EQ(p.pixels[2], Vec3(0.0f));
}

}  // namespace
}  // namespace hikari
