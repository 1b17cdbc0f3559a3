// Side-by-side pictures: each panel's pixels as they were, under a strip with its label.

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hikari/frame/side_by_side.h"

namespace hikari {
namespace {

Srgb8Image solid(int w, int h, uint8_t r, uint8_t g, uint8_t b) {
    Srgb8Image image(w, h);
    for (size_t i = 0; i < image.bytes.size(); i += 3)
        image.bytes[i] = r, image.bytes[i + 1] = g, image.bytes[i + 2] = b;
    return image;
}

/// Dark pixels (label ink) in columns [x0, x1) of rows [0, rows).
int ink_in(const Srgb8Image& image, int x0, int x1, int rows) {
    int n = 0;
    for (int y = 0; y < rows; ++y)
        for (int x = x0; x < x1; ++x) n += image.row(y)[3 * x] < 100;
    return n;
}

TEST(SideBySide, PanelsKeepTheirPixelsUnderTheirLabels) {
    const std::vector<Srgb8Image> panels = {solid(64, 10, 200, 0, 0), solid(64, 10, 0, 0, 200)};
    const std::vector<std::string> labels = {"zbuffer", "raytrace"};
    const Srgb8Image out = side_by_side(panels, labels);
    const PictureSize size = side_by_side_size({64, 10}, labels);
    ASSERT_EQ(out.width, size.width);
    ASSERT_EQ(out.height, size.height);
    EXPECT_EQ(out.width, 2 * 64 + k_panel_gap);
    const int strip = out.height - 10;
    EXPECT_EQ(strip, 12);  // "raytrace" at twice the font's size (94 pixels) does not fit 64
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 64; ++x) {
            EXPECT_EQ(out.row(strip + y)[3 * x], 200);
            EXPECT_EQ(out.row(strip + y)[3 * (x + 64 + k_panel_gap) + 2], 200);
        }
    EXPECT_GT(ink_in(out, 0, 64, strip), 20);
    EXPECT_GT(ink_in(out, 64 + k_panel_gap, out.width, strip), 20);
}

TEST(SideBySide, LabelsAreDoubledWhereTheyFitAndTheSizeStaysEven) {
    const std::vector<std::string> labels = {"wireframe", "zbuffer", "raytrace"};
    const PictureSize size = side_by_side_size({200, 150}, labels);
    EXPECT_EQ(size.width, 3 * 200 + 2 * k_panel_gap);
    EXPECT_EQ(size.height, 150 + 24);
    const std::vector<Srgb8Image> panels(3, solid(200, 150, 255, 255, 255));
    const Srgb8Image out = side_by_side(panels, labels);
    EXPECT_EQ(out.height, size.height);
    // The longest label, centred: its ink lies in the middle of its panel's strip.
    EXPECT_EQ(ink_in(out, 0, 40, 24), 0);
    EXPECT_GT(ink_in(out, 40, 160, 24), 100);
}

}  // namespace
}  // namespace hikari
