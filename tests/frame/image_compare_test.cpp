#include "hikari/frame/image_compare.h"

#include <cmath>

#include <gtest/gtest.h>

#include "hikari/core/color.h"

namespace hikari {
namespace {

/// A w × h image of one 8-bit sRGB grey level.
Image grey(int w, int h, int level) {
    const float v = srgb_to_linear(static_cast<float>(level) / 255.0f);
    return Image(w, h, Vec3(v));
}

TEST(ImageCompare, EqualImagesHaveInfinitePsnrAndNoDifference) {
    const Image a = grey(8, 4, 100);
    const ImageDifference d = compare_images(a, a, true);
    EXPECT_TRUE(std::isinf(d.psnr_db));
    EXPECT_EQ(d.differing, 0U);
    EXPECT_EQ(d.max_difference, 0.0);
    EXPECT_EQ(d.pixels, 32U);
}

TEST(ImageCompare, PsnrIsThe8BitToolsOne) {
    // One pixel of 32 differs by 10 levels in every channel: MSE = 100 / 32 in 8-bit units,
    // PSNR = 10 log10(255² · 32 / 100).
    const Image a = grey(8, 4, 100);
    Image b = a;
    b.pixels[13] = Vec3(srgb_to_linear(110.0f / 255.0f));
    const ImageDifference d = compare_images(a, b, true);
    EXPECT_NEAR(d.psnr_db, 10.0 * std::log10(255.0 * 255.0 * 32.0 / 100.0), 1e-9);
    EXPECT_NEAR(d.max_difference, 10.0 / 255.0, 1e-12);
    EXPECT_EQ(d.max_x, 5);
    EXPECT_EQ(d.max_y, 1);
    EXPECT_EQ(d.differing, 1U);
    // A tolerance above the linear difference counts it equal.
    EXPECT_EQ(compare_images(a, b, true, 1.0f).differing, 0U);
}

TEST(ImageCompare, DifferenceImageIsBlackWhereEqualAndBrightestAtTheMost) {
    const Image a = grey(4, 1, 50);
    Image b = a;
    b.pixels[1] = Vec3(srgb_to_linear(60.0f / 255.0f));
    b.pixels[3] = Vec3(srgb_to_linear(90.0f / 255.0f));
    const Image diff = difference_image(a, b, 40.0 / 255.0);
    EXPECT_EQ(diff.pixels[0], Vec3(0.0f));
    EXPECT_EQ(diff.pixels[2], Vec3(0.0f));
    EXPECT_GT(diff.pixels[1].z, 0.0f);  // a quarter of the way: toward blue
    EXPECT_GT(diff.pixels[3].y, 0.5f);  // the largest: yellow
    EXPECT_GT(diff.pixels[3].x, 0.5f);
}

TEST(ImageCompare, NaNEqualsNaNAndIsCounted) {
    Image a = grey(4, 2, 100);
    a.pixels[1].y = std::nanf("");
    a.pixels[6] = Vec3(std::nanf(""));
    const ImageDifference same = compare_images(a, a);
    EXPECT_EQ(same.differing, 0U);
    EXPECT_EQ(same.max_difference, 0.0);
    EXPECT_TRUE(std::isinf(same.psnr_db));
    EXPECT_EQ(same.not_a_number_a, 2U);
    EXPECT_EQ(same.not_a_number_b, 2U);
}

TEST(ImageCompare, NaNAgainstANumberDiffersByTheMost) {
    Image a = grey(4, 2, 100);
    const Image b = a;
    a.pixels[5].z = std::nanf("");
    const ImageDifference d = compare_images(a, b);
    EXPECT_EQ(d.differing, 1U);
    EXPECT_EQ(d.max_difference, 1.0);
    EXPECT_EQ(d.max_x, 1);
    EXPECT_EQ(d.max_y, 1);
    EXPECT_NEAR(d.psnr_db, 10.0 * std::log10(3.0 * 8.0), 1e-9);  // MSE = 1 / 24
    EXPECT_EQ(d.not_a_number_a, 1U);
    EXPECT_EQ(d.not_a_number_b, 0U);
}

}  // namespace
}  // namespace hikari
