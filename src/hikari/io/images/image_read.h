#pragma once
// Reading images into linear RGB: reference images for tests, and later textures.

#include <filesystem>
#include <string>

#include "hikari/core/image.h"

namespace hikari {

/// The largest image read_image() accepts: 65536 pixels per side and 2^28 pixels in all
/// (1 GiB of 8-bit RGBA), so a corrupt header cannot make us allocate without bound.
inline constexpr int k_max_image_side = 65536;
inline constexpr size_t k_max_image_pixels = size_t{1} << 28;

/// Reads `path` into a linear-RGB Image (row 0 at the top), by extension (case-insensitive):
/// - `.png`, `.jpg`, `.jpeg` (stb_image; 8- or 16-bit, sRGB-decoded to linear; grey is
///   replicated, alpha dropped);
/// - `.ppm` (binary P6 or ASCII P3, maxval up to 65535, sRGB-decoded to linear);
/// - `.pfm` (PF colour or Pf grey, either byte order, multiplied by |scale|);
/// - `.exr` (tinyexr; RGB(A) or single channel, linear as stored);
/// - `.hdr` (Radiance RGBE through stb_image, linear as stored).
/// Throws InputError naming the file and the reason for a missing, unreadable, truncated or
/// malformed file, an unknown extension, or a size beyond the limits above.
Image read_image(const std::filesystem::path& path);

/// Decodes a PNG or JPEG image held in memory (an image embedded in a glTF file), as read_image()
/// decodes such a file; `name` stands for the image in error messages ("NAME: reason").
Image decode_png_or_jpeg(const std::filesystem::path& name, const std::string& bytes);

}  // namespace hikari
