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

/// How the integer samples of .png, .ppm, .jpg and .xlsx hold linear values in [0, 1].
enum class SampleEncoding {
    /// The sRGB curve (IEC 61966-2-1, core/color.h): what screens and viewers expect, so the
    /// picture looks as the light computed it. The default.
    srgb,
    /// round(255 · v) (65535 · v at 16 bits), no curve: what the lecture's sample code writes, so
    /// a student's file can be compared byte for byte (the stage-1 sphere's kd (0.8, 0.3, 0.2)
    /// is (204, 77, 51) here, (231, 149, 124) in sRGB). Looks darker on screen.
    linear,
};

/// What write_image() leaves to the caller.
struct ImageWriteSettings {
    int bit_depth = 8;  ///< bits per integer sample: 8, or 16 for .png and .ppm only
    SampleEncoding encoding = SampleEncoding::srgb;  ///< of the integer formats; floats stay linear
};

/// `image` as 8-bit samples round(255 · clamp(v, 0, 1)) (NaN as 0): SampleEncoding::linear.
Srgb8Image encode_linear8(const Image& image);

/// True when `path`'s format can hold sRGB samples of `bit_depth` bits: 8 for every format
/// (the float ones ignore it), 16 for .png and .ppm; false for any other depth.
bool supports_bit_depth(const std::filesystem::path& path, int bit_depth);

/// Writes the linear-RGB `image` to `path` in the format its extension names:
/// - `.png`: RGB, sRGB-encoded (or linear, settings.encoding), values clamped to [0, 1]; 8 bits per
/// sample, or 16
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
