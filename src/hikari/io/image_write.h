#pragma once
// Writing rendered images: 8-bit sRGB for viewing (.png .ppm), linear float for analysis (.pfm
// .exr).

#include <filesystem>

#include "hikari/core/image.h"

namespace hikari {

/// The extensions write_image() accepts, for messages: ".png, .ppm, .pfm, .exr, .xlsx".
inline constexpr const char* k_writable_image_extensions = ".png, .ppm, .pfm, .exr, .xlsx";

/// True when write_image() can write `path`, judged by its extension alone (case-insensitive).
/// Lets the command line reject `-o picture.bmp` before spending time on a render.
bool is_supported_image_extension(const std::filesystem::path& path);

/// Writes the linear-RGB `image` to `path` in the format its extension names:
/// - `.png`: 8-bit RGB, sRGB-encoded, values clamped to [0, 1];
/// - `.ppm`: binary P6, 8-bit, sRGB-encoded and clamped like PNG;
/// - `.pfm`: 32-bit float linear RGB, unclamped, little-endian, rows bottom to top;
/// - `.exr`: 32-bit float linear RGB (channels stored B, G, R), unclamped, ZIP-compressed.
/// - `.xlsx`: a workbook whose cells are the pixels (io/xlsx_write.h), sRGB-encoded and clamped
///   like PNG.
/// The file is written atomically (see write_file_atomically). Throws InputError for an unknown
/// extension, an empty image, or any OS error.
void write_image(const std::filesystem::path& path, const Image& image);

/// Writes the 8-bit sRGB `image` to `path`, which must name a `.png` or `.ppm` file (the same
/// bytes as write_image of the linear image it encodes). Throws InputError as write_image does,
/// and for a float format.
void write_image(const std::filesystem::path& path, const Srgb8Image& image);

}  // namespace hikari
