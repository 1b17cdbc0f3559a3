#pragma once
// Writing rendered images: sRGB for viewing (.png .ppm .jpg .xlsx; 8-bit, or 16-bit PNG and
// PPM), linear float for analysis (.pfm .exr .hdr).

#include <cstdint>
#include <filesystem>
#include <vector>

#include "hikari/core/image.h"

namespace hikari {

/// The extensions write_image() accepts, for messages.
inline constexpr const char* k_writable_image_extensions =
    ".png, .ppm, .jpg, .jpeg, .pfm, .exr, .hdr, .xlsx";

/// True when write_image() can write `path`, judged by its extension alone (case-insensitive).
/// Lets the command line reject `-o picture.bmp` before spending time on a render.
bool is_supported_image_extension(const std::filesystem::path& path);

/// What write_image() leaves to the caller.
struct ImageWriteSettings {
    int bit_depth = 8;  ///< bits per sRGB sample: 8, or 16 for .png and .ppm only
};

/// True when `path`'s format can hold sRGB samples of `bit_depth` bits: 8 for every format
/// (the float ones ignore it), 16 for .png and .ppm; false for any other depth.
bool supports_bit_depth(const std::filesystem::path& path, int bit_depth);

/// Writes the linear-RGB `image` to `path` in the format its extension names:
/// - `.png`: RGB, sRGB-encoded, values clamped to [0, 1]; 8 bits per sample, or 16
///   (round(65535 · sRGB(v)), settings.bit_depth = 16);
/// - `.ppm`: binary P6, sRGB-encoded and clamped like PNG; maxval 255, or 65535 (big-endian
///   samples) for 16 bits;
/// - `.jpg`, `.jpeg`: baseline JPEG (stb_image_write), 8-bit sRGB clamped like PNG, quality 95;
/// - `.pfm`: 32-bit float linear RGB, unclamped, little-endian, rows bottom to top;
/// - `.exr`: 32-bit float linear RGB (channels stored B, G, R), unclamped, ZIP-compressed;
/// - `.hdr`: Radiance RGBE (stb_image_write), linear and unclamped above (8 bits of mantissa
///   per channel, one shared exponent); negative values and NaN are stored as 0;
/// - `.xlsx`: a workbook whose cells are the pixels (io/xlsx_write.h), sRGB-encoded and clamped
///   like PNG.
/// The file is written atomically (see write_file_atomically). Throws InputError for an unknown
/// extension, a bit depth the format cannot hold, an empty image, or any OS error.
void write_image(const std::filesystem::path& path, const Image& image,
                 const ImageWriteSettings& settings = {});

/// The bytes write_image would write to `path` (its extension picks the format), for a front end
/// that sends them elsewhere (`hikari serve`'s frames). Throws InputError as write_image does.
std::vector<uint8_t> encode_image(const std::filesystem::path& path, const Image& image,
                                  const ImageWriteSettings& settings = {});
std::vector<uint8_t> encode_image(const std::filesystem::path& path, const Srgb8Image& image);

/// Writes the 8-bit sRGB `image` to `path`, which must name a `.png`, `.ppm`, `.jpg`/`.jpeg` or
/// `.xlsx` file (the same bytes as write_image of the linear image it encodes, at 8 bits).
/// Throws InputError as write_image does, and for a float format.
void write_image(const std::filesystem::path& path, const Srgb8Image& image);

}  // namespace hikari
