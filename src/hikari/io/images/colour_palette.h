#pragma once
// Reducing an 8-bit image to a few thousand colours: what a spreadsheet can hold (Excel allows
// at most 64,000 cell formats per workbook, one per fill colour). Median cut (Heckbert 1982,
// "Color image quantization for frame buffer display"): the box of colours with the most pixels
// along its longest side is split at its median until there are enough boxes; each box's colour
// is the mean of its pixels.

#include <array>
#include <cstdint>
#include <vector>

#include "hikari/core/image.h"

namespace hikari {

/// An image as palette indices.
struct PalettedImage {
    int width = 0, height = 0;
    std::vector<std::array<uint8_t, 3>> palette;  ///< at most the size asked for
    std::vector<uint16_t> index;                  ///< per pixel, row-major from the top
};

/// `image` reduced to at most `max_colours` colours (1 to 65,536) by median cut, each pixel
/// given its box's mean colour (no dithering). An image with at most `max_colours` distinct
/// colours keeps them exactly.
PalettedImage median_cut(const Srgb8Image& image, int max_colours);

}  // namespace hikari
