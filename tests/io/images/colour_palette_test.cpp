// Median-cut colour reduction (io/colour_palette.h): exact when the colours fit, at most the
// palette asked for otherwise, every pixel near its own colour.
#include "hikari/io/images/colour_palette.h"

#include <cstdlib>
#include <set>

#include <gtest/gtest.h>

#include "hikari/core/rng.h"

namespace hikari {
namespace {

Srgb8Image random_image(int w, int h, uint32_t seed) {
    Srgb8Image image(w, h);
    Pcg32 rng(seed, 1);
    for (uint8_t& b : image.bytes) b = static_cast<uint8_t>(rng.next_u32());
    return image;
}

std::array<uint8_t, 3> pixel(const Srgb8Image& image, size_t i) {
    return {image.bytes[3 * i], image.bytes[3 * i + 1], image.bytes[3 * i + 2]};
}

TEST(ColourPalette, FewColoursAreKeptExactly) {
    Srgb8Image image(5, 4);
    const uint8_t colours[3][3] = {{255, 0, 0}, {0, 128, 255}, {7, 7, 7}};
    for (size_t i = 0; i < 20; ++i)
        for (int c = 0; c < 3; ++c) image.bytes[3 * i + c] = colours[i % 3][c];
    const PalettedImage p = median_cut(image, 4096);
    EXPECT_EQ(p.palette.size(), 3u);
    for (size_t i = 0; i < 20; ++i) EXPECT_EQ(p.palette[p.index[i]], pixel(image, i)) << i;
}

TEST(ColourPalette, ManyColoursShareAPaletteOfTheSizeAsked) {
    const Srgb8Image image = random_image(200, 150, 3);  // ~30,000 distinct colours
    for (const int size : {1, 16, 4096}) {
        const PalettedImage p = median_cut(image, size);
        EXPECT_EQ(p.palette.size(), static_cast<size_t>(size));
        std::set<uint16_t> used(p.index.begin(), p.index.end());
        EXPECT_EQ(used.size(), static_cast<size_t>(size));
    }
    // With 4096 boxes of a uniform cube, each channel is within a box's half width (256 / 16).
    const PalettedImage fine = median_cut(image, 4096);
    double error = 0;
    for (size_t i = 0; i < fine.index.size(); ++i)
        for (int c = 0; c < 3; ++c)
            error += std::abs(int(fine.palette[fine.index[i]][c]) - int(pixel(image, i)[c]));
    EXPECT_LT(error / (3.0 * fine.index.size()), 8.0);
}

}  // namespace
}  // namespace hikari
