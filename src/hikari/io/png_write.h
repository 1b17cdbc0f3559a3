#pragma once
// A PNG encoder (ISO/IEC 15948) built for speed on renders: rows are filtered and compressed in
// independent bands, in parallel, each band its own DEFLATE piece and IDAT chunk.

#include <cstdint>
#include <vector>

#include "hikari/core/image.h"
#include "hikari/core/simd_level.h"

namespace hikari {

/// The sRGB `image` (non-empty) as the bytes of an 8-bit RGB PNG file. The bytes depend neither
/// on the thread count nor on the SIMD `level` the row filters and checksum run at.
std::vector<uint8_t> encode_png(const Srgb8Image& image, SimdLevel level = best_simd_level());

}  // namespace hikari
