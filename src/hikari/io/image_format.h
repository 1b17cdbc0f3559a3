#pragma once
// Image file formats known to io/, recognised by file name extension.

#include <filesystem>
#include <optional>

namespace hikari {

/// An image file format. Png/Jpeg hold 8-bit sRGB, Ppm 8/16-bit sRGB, Pfm/Exr linear float,
/// Hdr (Radiance RGBE) linear, read only; Xlsx a spreadsheet whose cells are 8-bit sRGB pixels,
/// write only.
enum class ImageFormat { Png, Jpeg, Ppm, Pfm, Exr, Hdr, Xlsx };

/// The format named by the extension of `path`, case-insensitive (`.png`, `.jpg`/`.jpeg`,
/// `.ppm`, `.pfm`, `.exr`, `.hdr`, `.xlsx`); nullopt for any other extension.
std::optional<ImageFormat> image_format_from_extension(const std::filesystem::path& path);

}  // namespace hikari
