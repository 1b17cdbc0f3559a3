#pragma once
// A small bitmap font for labels drawn into pictures (the method names over the panels of
// `hikari render --side-by-side`): 5 × 9 font pixels a character, 7 above the baseline and 2
// below for the descenders of g, j, p, q and y. It has the lowercase letters, the digits and
// - . , : / ( ) + = and space, what method names and short labels use; an uppercase letter is
// drawn as its lowercase form, and any other character as an empty box, so that a missing glyph
// shows rather than vanishes.

#include <array>
#include <cstdint>
#include <string_view>

#include "hikari/core/image.h"

namespace hikari {

/// Font pixels of one character: its ink, and the step to the next character (one pixel of space).
constexpr int k_glyph_width = 5;
constexpr int k_glyph_height = 9;
constexpr int k_glyph_advance = 6;

/// The pixels of character `c`: row r (0 at the top) is `rows[r]`, with '#' for ink and '.' for
/// none, k_glyph_width characters each.
std::array<std::string_view, k_glyph_height> glyph_rows(char c);

/// Columns of picture pixels of `text` drawn at `scale` (each font pixel scale × scale picture
/// pixels): its characters' advances less the space after the last.
int text_width(std::string_view text, int scale);

/// The columns [x0, x1) of a picture that a drawing may touch.
struct ColumnRange {
    int x0 = 0, x1 = 0;
};

/// Draws `text` into `image` in the 8-bit sRGB colour `rgb`, the top left of its first character
/// at (x, y), each font pixel a scale × scale square; ink outside `clip` or the image is left
/// out, so a label too wide for its panel is cut at the panel's edge.
void draw_text(Srgb8Image& image, int x, int y, std::string_view text, int scale,
               std::array<uint8_t, 3> rgb, ColumnRange clip);

}  // namespace hikari
