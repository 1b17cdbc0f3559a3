#pragma once
// Image file formats known to io/, recognised by file name extension.

#include <filesystem>
#include <optional>

namespace hikari {

/// An image file format. Png/Ppm hold 8- or 16-bit sRGB, Jpeg 8-bit sRGB, Pfm/Exr linear float,
/// Hdr (Radiance RGBE) linear; Xlsx a spreadsheet whose cells are 8-bit sRGB pixels, write
/// only.
enum class ImageFormat { Png, Jpeg, Ppm, Pfm, Exr, Hdr, Xlsx };

/// The format named by the extension of `path`, case-insensitive (`.png`, `.jpg`/`.jpeg`,
/// `.ppm`, `.pfm`, `.exr`, `.hdr`, `.xlsx`); nullopt for any other extension.
std::optional<ImageFormat> image_format_from_extension(const std::filesystem::path& path);

/// True for the formats that hold display values, sRGB-encoded and clamped to [0, 1] (Png, Jpeg,
/// Ppm, Xlsx): low dynamic range, the ones a tone map is for. The others keep linear radiance.
bool is_low_dynamic_range(ImageFormat format);

}  // namespace hikari
