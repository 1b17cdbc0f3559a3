#pragma once
// Line drawings as SVG (the vector form of the lecture's Fig 4.1a, c): one <line> per segment,
// in pixel coordinates, so that the file shows the same picture as the PNG at any scale.

#include <filesystem>
#include <string>

#include "hikari/frame/line_drawing.h"

namespace hikari {

/// The SVG document of `drawing`: viewBox "0 0 width height" (pixels, y down), a background
/// rectangle, and each segment as a <line> with its sRGB-encoded colour, stroke-width the line
/// width and butt ends, in the drawing's order.
std::string svg_document(const LineDrawing& drawing);

/// Writes svg_document(drawing) to `path`, whole or not at all (io/atomic_file.h).
void write_svg(const std::filesystem::path& path, const LineDrawing& drawing);

/// Whether `path` names an SVG file (extension .svg, any case).
bool is_svg_path(const std::filesystem::path& path);

}  // namespace hikari
