#include "hikari/io/images/svg_write.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <iterator>
#include <span>

#include <fmt/format.h>

#include "hikari/core/color.h"
#include "hikari/io/files/atomic_file.h"

namespace hikari {

namespace {

/// `c` as an sRGB hex colour, #rrggbb.
std::string hex_color(Vec3 c) {
    return fmt::format("#{:02x}{:02x}{:02x}", linear_to_srgb8(c.x), linear_to_srgb8(c.y),
                       linear_to_srgb8(c.z));
}

}  // namespace

std::string svg_document(const LineDrawing& d) {
    std::string out;
    auto it = std::back_inserter(out);
    fmt::format_to(it, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    fmt::format_to(it,
                   "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
                   "viewBox=\"0 0 {0} {1}\">\n",
                   d.width, d.height);
    fmt::format_to(it, "<rect width=\"{}\" height=\"{}\" fill=\"{}\"/>\n", d.width, d.height,
                   hex_color(d.background));
    fmt::format_to(it, "<g fill=\"none\" stroke-width=\"{}\" stroke-linecap=\"butt\">\n",
                   d.line_width);
    for (const LineSegment& s : d.segments)
        fmt::format_to(it,
                       "<line x1=\"{:.3f}\" y1=\"{:.3f}\" x2=\"{:.3f}\" y2=\"{:.3f}\" "
                       "stroke=\"{}\"/>\n",
                       s.a.x, s.a.y, s.b.x, s.b.y, hex_color(s.color));
    fmt::format_to(it, "</g>\n</svg>\n");
    return out;
}

void write_svg(const std::filesystem::path& path, const LineDrawing& drawing) {
    const std::string text = svg_document(drawing);
    write_file_atomically(path,
                          std::span(reinterpret_cast<const uint8_t*>(text.data()), text.size()));
}

bool is_svg_path(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".svg";
}

}  // namespace hikari
