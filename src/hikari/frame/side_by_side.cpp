#include "hikari/frame/side_by_side.h"

#include <algorithm>
#include <array>
#include <cstring>

#include "hikari/frame/bitmap_font.h"

namespace hikari {

namespace {

constexpr std::array<uint8_t, 3> k_strip_colour = {240, 240, 240};
constexpr std::array<uint8_t, 3> k_text_colour = {30, 30, 30};

/// Font pixels of the strip: a margin of 2 above the glyphs' 9 rows and 1 below.
constexpr int k_strip_font_pixels = 12;

/// Twice the font's size where a label of `characters` fits a panel `panel_width` wide.
int label_scale(int panel_width, size_t characters) {
    const int doubled = text_width(std::string(characters, 'm'), 2);
    return doubled + 4 <= panel_width ? 2 : 1;
}

/// The scale every label is drawn at: one for all, so the strips match.
int common_scale(int panel_width, std::span<const std::string> labels) {
    size_t longest = 0;
    for (const std::string& l : labels) longest = std::max(longest, l.size());
    return label_scale(panel_width, longest);
}

}  // namespace

PictureSize side_by_side_size(PictureSize panel, std::span<const std::string> labels) {
    const int count = static_cast<int>(labels.size());
    return {count * panel.width + (count - 1) * k_panel_gap,
            panel.height + k_strip_font_pixels * common_scale(panel.width, labels)};
}

Srgb8Image side_by_side(std::span<const Srgb8Image> panels, std::span<const std::string> labels) {
    const int w = panels.front().width, h = panels.front().height;
    const int scale = common_scale(w, labels);
    const int strip = k_strip_font_pixels * scale;
    const PictureSize size = side_by_side_size({w, h}, labels);
    Srgb8Image out(size.width, size.height);
    // The strip colour everywhere: the label strips and the gaps between panels.
    for (size_t i = 0; i < out.bytes.size(); i += 3)
        std::copy(k_strip_colour.begin(), k_strip_colour.end(), out.bytes.data() + i);
    for (size_t p = 0; p < panels.size(); ++p) {
        const int left = static_cast<int>(p) * (w + k_panel_gap);
        for (int y = 0; y < h; ++y)
            std::memcpy(out.row(strip + y) + 3 * left, panels[p].row(y),
                        static_cast<size_t>(w) * 3);
        const int text = text_width(labels[p], scale);
        draw_text(out, left + std::max(0, (w - text) / 2), 2 * scale, labels[p], scale,
                  k_text_colour, {left, left + w});
    }
    return out;
}

}  // namespace hikari
