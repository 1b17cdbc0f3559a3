#pragma once
// A PNG encoder (ISO/IEC 15948) built for speed on renders: rows are filtered and compressed in
// independent bands, in parallel, each band its own DEFLATE piece and IDAT chunk.

#include <cstdint>
#include <vector>

#include "hikari/core/image.h"
#include "hikari/core/simd_level.h"

namespace hikari {

/// Row-major 16-bit sRGB RGB samples, row 0 at the top, each stored big-endian (most
/// significant byte first, the order of 16-bit PNG and PPM files): 6 bytes per pixel.
struct Srgb16Image {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> bytes;
};

/// `image` with each channel sRGB-encoded to 16 bits: round(65535 · linear_to_srgb(v)), the
/// curve of the 8-bit writers (core/color.h), so values outside [0, 1] and NaN clamp as there.
Srgb16Image encode_srgb16(const Image& image);

/// The sRGB `image` (non-empty) as the bytes of an 8-bit RGB PNG file. The bytes depend neither
/// on the thread count nor on the SIMD `level` the row filters and checksum run at.
std::vector<uint8_t> encode_png(const Srgb8Image& image, SimdLevel level = best_simd_level());

/// The same for a 16-bit image: a 16-bit RGB PNG file (its row filters run portable code at
/// every `level`).
std::vector<uint8_t> encode_png(const Srgb16Image& image, SimdLevel level = best_simd_level());

}  // namespace hikari
