#pragma once
// Rendering into Excel (the lecture's last slide: Excelでレンダリング！): an image as a workbook
// whose cells are its pixels.

#include <cstdint>
#include <filesystem>
#include <vector>

#include "hikari/core/image.h"

namespace hikari {

/// Excel's sheet limits: columns and rows per worksheet.
inline constexpr int k_xlsx_max_columns = 16384;
inline constexpr int k_xlsx_max_rows = 1048576;
/// Fill colours a workbook gets at most: Excel allows 64,000 cell formats; median cut
/// (io/colour_palette.h) brings any image down to this many.
inline constexpr int k_xlsx_palette_colours = 4096;

/// `image` as an .xlsx workbook (libxlsxwriter, rows streamed in its constant-memory mode):
/// - sheet "image": one square cell (12 × 12 pixels) per pixel, filled with the pixel's sRGB colour
///   reduced to at most k_xlsx_palette_colours colours (exact when the image has no more), no
///   gridlines, printed on one page;
/// - sheets "red", "green", "blue": the same grid holding each pixel's 8-bit sRGB channel
///   (0–255, before the palette) as a number, for formulas.
/// Throws InputError naming `path` for an image larger than a sheet or a failed write.
std::vector<uint8_t> encode_xlsx(const std::filesystem::path& path, const Srgb8Image& image);

}  // namespace hikari
