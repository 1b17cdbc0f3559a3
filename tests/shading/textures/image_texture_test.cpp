#include "hikari/shading/textures/image_texture.h"

#include <cmath>

#include <gtest/gtest.h>

#include "../../support/expect_near.h"
#include "hikari/shading/textures/mip_pyramid.h"

namespace hikari {
namespace {

using testing::expect_near;

/// A 2×2 image: red at the top left, green top right, blue bottom left, white bottom right.
Image quad_image() {
    Image image(2, 2);
    image.at(0, 0) = {1, 0, 0};
    image.at(1, 0) = {0, 1, 0};
    image.at(0, 1) = {0, 0, 1};
    image.at(1, 1) = {1, 1, 1};
    return image;
}

ImageTexture texture_of(Image image, TextureFilter filter, TextureWrap wrap) {
    ImageTexture t;
    t.pyramid = std::make_shared<const MipPyramid>(build_mip_pyramid(std::move(image)));
    t.filter = filter;
    t.wrap = wrap;
    return t;
}

TEST(ImageTexture, WrapTexelRepeatsAndClamps) {
    EXPECT_EQ(wrap_texel(-1, 4, TextureWrap::repeat), 3);
    EXPECT_EQ(wrap_texel(-5, 4, TextureWrap::repeat), 3);
    EXPECT_EQ(wrap_texel(9, 4, TextureWrap::repeat), 1);
    EXPECT_EQ(wrap_texel(-1, 4, TextureWrap::clamp), 0);
    EXPECT_EQ(wrap_texel(9, 4, TextureWrap::clamp), 3);
}

/// A lookup of quad_image() and the colour it must give.
struct Lookup {
    Vec3 (*sample)(const Image&, float, float, TextureWrap);
    float u, v;
    TextureWrap wrap;
    Vec3 expected;
    const char* why;
};

TEST(ImageTexture, LookupsFollowTheUvConventionAndWrapModes) {
    const Lookup lookups[] = {
        // (0, 0) is the lower-left corner.
        {sample_nearest, 0.25f, 0.25f, TextureWrap::repeat, {0, 0, 1}, "lower left"},
        {sample_nearest, 0.75f, 0.25f, TextureWrap::repeat, {1, 1, 1}, "lower right"},
        {sample_nearest, 0.25f, 0.75f, TextureWrap::repeat, {1, 0, 0}, "upper left"},
        {sample_nearest, 0.75f, 0.75f, TextureWrap::repeat, {0, 1, 0}, "upper right"},
        // Texel centres sit at half-integer texel coordinates: u = (x + 0.5) / width.
        {sample_bilinear, 0.25f, 0.75f, TextureWrap::clamp, {1, 0, 0}, "a texel centre"},
        {sample_bilinear, 0.75f, 0.25f, TextureWrap::clamp, {1, 1, 1}, "another centre"},
        {sample_bilinear, 0.5f, 0.75f, TextureWrap::clamp, {0.5f, 0.5f, 0}, "between two"},
        {sample_bilinear, 0.5f, 0.5f, TextureWrap::clamp, {0.5f, 0.5f, 0.5f}, "between four"},
        // At u = 0 on the top row: clamp sees only the left texel, repeat blends in the right.
        {sample_bilinear, 0.0f, 0.75f, TextureWrap::clamp, {1, 0, 0}, "clamped edge"},
        {sample_bilinear, 0.0f, 0.75f, TextureWrap::repeat, {0.5f, 0.5f, 0}, "repeated edge"},
        // Repeat tiles: far coordinates keep their fraction; clamp extends the border.
        {sample_nearest, 1000.25f, -99.25f, TextureWrap::repeat, {1, 0, 0}, "far repeat"},
        {sample_nearest, 7.0f, -3.0f, TextureWrap::clamp, {1, 1, 1}, "far clamp"},
    };
    const Image image = quad_image();
    for (const Lookup& l : lookups) {
        SCOPED_TRACE(l.why);
        expect_near(l.sample(image, l.u, l.v, l.wrap), l.expected, 1e-6f);
    }
}

TEST(ImageTexture, LevelOfDetailIsLog2OfTheFootprintInTexels) {
    const MipPyramid pyramid = build_mip_pyramid(Image(256, 128));
    ASSERT_EQ(pyramid.levels.size(), 9u);  // 256 × 128 down to 1 × 1
    EXPECT_FLOAT_EQ(mip_level_of_detail(pyramid, 0, 0, 0, 0), 0.0f);
    EXPECT_FLOAT_EQ(mip_level_of_detail(pyramid, 4.0f / 256, 0, 0, 0), 2.0f);
    // The longer axis decides: v changes 8 texels (of 128) per pixel step along y.
    EXPECT_FLOAT_EQ(mip_level_of_detail(pyramid, 1.0f / 256, 0, 0, 8.0f / 128), 3.0f);
    // Magnified textures use level 0, huge footprints the 1 × 1 level.
    EXPECT_FLOAT_EQ(mip_level_of_detail(pyramid, 0.1f / 256, 0, 0, 0), 0.0f);
    EXPECT_FLOAT_EQ(mip_level_of_detail(pyramid, 50.0f, 0, 0, 0), 8.0f);
}

TEST(ImageTexture, TrilinearBlendsTheTwoLevelsAroundTheLevelOfDetail) {
    // Columns alternate black and white: level 0 is a stripe pattern, level 1 grey.
    Image stripes(8, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) stripes.at(x, y) = Vec3(static_cast<float>(x % 2));
    const ImageTexture t = texture_of(stripes, TextureFilter::trilinear, TextureWrap::repeat);
    const float u = 1.5f / 8, v = 0.5f;  // the centre of a white texel
    expect_near(sample_image_texture(t, u, v, 0, 0, 0, 0), Vec3(1.0f), 1e-6f);
    expect_near(sample_image_texture(t, u, v, 2.0f / 8, 0, 0, 0), Vec3(0.5f), 1e-6f);
    // Level of detail 0.5: halfway between white and the grey of level 1.
    expect_near(sample_image_texture(t, u, v, std::sqrt(2.0f) / 8, 0, 0, 0), Vec3(0.75f), 1e-5f);
    // The bilinear filter ignores the footprint and aliases.
    const ImageTexture b = texture_of(stripes, TextureFilter::bilinear, TextureWrap::repeat);
    expect_near(sample_image_texture(b, u, v, 2.0f / 8, 0, 0, 0), Vec3(1.0f), 1e-6f);
}

TEST(ImageTexture, TextureColourReadsTheSurfacePoint) {
    const ImageTexture t = texture_of(quad_image(), TextureFilter::nearest, TextureWrap::repeat);
    SurfacePoint<float> p;
    p.u = 0.75f;
    p.v = 0.75f;
    expect_near(texture_colour<float>(t, p), {0, 1, 0}, 1e-6f);
}

TEST(MipPyramid, HalvesDownToOneTexelRoundingDown) {
    const MipPyramid pyramid = build_mip_pyramid(Image(5, 3, Vec3(0.25f)));
    ASSERT_EQ(pyramid.levels.size(), 3u);
    EXPECT_EQ(pyramid.levels[1].width, 2);
    EXPECT_EQ(pyramid.levels[1].height, 1);
    EXPECT_EQ(pyramid.levels[2].width, 1);
    EXPECT_EQ(pyramid.levels[2].height, 1);
    for (const Image& level : pyramid.levels)
        for (const Vec3& texel : level.pixels) expect_near(texel, Vec3(0.25f), 1e-6f);
}

TEST(MipPyramid, EveryLevelKeepsTheMeanOfANonPowerOfTwoImage) {
    Image image(7, 5);
    Vec3 sum(0.0f);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) {
            image.at(x, y) = Vec3(static_cast<float>(x * x), static_cast<float>(y), 1.0f);
            sum += image.at(x, y);
        }
    const Vec3 mean = sum * (1.0f / 35);
    const MipPyramid pyramid = build_mip_pyramid(image);
    for (const Image& level : pyramid.levels) {
        Vec3 level_sum(0.0f);
        for (const Vec3& texel : level.pixels) level_sum += texel;
        expect_near(level_sum * (1.0f / static_cast<float>(level.pixels.size())), mean, 1e-4f);
    }
}

TEST(MipPyramid, EvenSizesAverageTwoByTwoBlocks) {
    const MipPyramid pyramid = build_mip_pyramid(quad_image());
    ASSERT_EQ(pyramid.levels.size(), 2u);
    expect_near(pyramid.levels[1].at(0, 0), {0.5f, 0.5f, 0.5f}, 1e-6f);
}

TEST(MipPyramid, NonFiniteTexelsBecomeZero) {
    Image image(2, 1, Vec3(1.0f));
    image.at(0, 0) = Vec3(std::nanf(""), INFINITY, 1.0f);
    const MipPyramid pyramid = build_mip_pyramid(image);
    expect_near(pyramid.levels[0].at(0, 0), Vec3(0.0f), 1e-6f);
    expect_near(pyramid.levels[1].at(0, 0), Vec3(0.5f), 1e-6f);
}

}  // namespace
}  // namespace hikari
