#include "hikari/frame/bitmap_font.h"

#include <algorithm>

namespace hikari {

namespace {

/// Characters drawn side by side, as a banner: glyph i of `chars` is columns
/// [i·k_glyph_advance, i·k_glyph_advance + k_glyph_width) of every row, so the table reads as the
/// letters it holds.
struct GlyphSheet {
    std::string_view chars;
    std::array<std::string_view, k_glyph_height> rows;
};

// clang-format off
constexpr GlyphSheet k_sheets[] = {
    {"abcdefghijklm",
     {"..... #.... ..... ....# ..... ..##. ..... #.... ..#.. ...#. #.... .##.. .....",
      "..... #.... ..... ....# ..... .#... ..... #.... ..... ..... #.... ..#.. .....",
      ".###. ####. .#### .#### .###. ####. .#### ####. .##.. ..##. #..#. ..#.. ##.#.",
      "....# #...# #.... #...# #...# .#... #...# #...# ..#.. ...#. #.#.. ..#.. #.#.#",
      ".#### #...# #.... #...# ##### .#... #...# #...# ..#.. ...#. ##... ..#.. #.#.#",
      "#...# #...# #.... #...# #.... .#... #...# #...# ..#.. ...#. #.#.. ..#.. #.#.#",
      ".#### ####. .#### .#### .###. .#... .#### #...# .###. ...#. #..#. .###. #.#.#",
      "..... ..... ..... ..... ..... ..... ....# ..... ..... #..#. ..... ..... .....",
      "..... ..... ..... ..... ..... ..... .###. ..... ..... .##.. ..... ..... ....."}},
    {"nopqrstuvwxyz",
     {"..... ..... ..... ..... ..... ..... .#... ..... ..... ..... ..... ..... .....",
      "..... ..... ..... ..... ..... ..... .#... ..... ..... ..... ..... ..... .....",
      "####. .###. ####. .#### #.##. .#### ####. #...# #...# #...# #...# #...# #####",
      "#...# #...# #...# #...# ##..# #.... .#... #...# #...# #...# .#.#. #...# ...#.",
      "#...# #...# #...# #...# #.... .###. .#... #...# #...# #.#.# ..#.. #...# ..#..",
      "#...# #...# #...# #...# #.... ....# .#..# #...# .#.#. #.#.# .#.#. #...# .#...",
      "#...# .###. ####. .#### #.... ####. ..##. .#### ..#.. .#.#. #...# .#### #####",
      "..... ..... #.... ....# ..... ..... ..... ..... ..... ..... ..... ....# .....",
      "..... ..... #.... ....# ..... ..... ..... ..... ..... ..... ..... .###. ....."}},
    {"0123456789",
     {".###. ..#.. .###. ####. ...#. ##### ..##. ##### .###. .###.",
      "#...# .##.. #...# ....# ..##. #.... .#... ....# #...# #...#",
      "#..## ..#.. ....# ....# .#.#. ####. #.... ...#. #...# #...#",
      "#.#.# ..#.. ...#. .###. #..#. ....# ####. ..#.. .###. .####",
      "##..# ..#.. ..#.. ....# ##### ....# #...# .#... #...# ....#",
      "#...# ..#.. .#... ....# ...#. #...# #...# .#... #...# ...#.",
      ".###. .###. ##### ####. ...#. .###. .###. .#... .###. .##..",
      "..... ..... ..... ..... ..... ..... ..... ..... ..... .....",
      "..... ..... ..... ..... ..... ..... ..... ..... ..... ....."}},
    {"-.,:/()+= ",
     {"..... ..... ..... ..... ....# ...#. .#... ..... ..... .....",
      "..... ..... ..... ..... ....# ..#.. ..#.. ..... ..... .....",
      "..... ..... ..... ..#.. ...#. .#... ...#. ..#.. ..... .....",
      "..... ..... ..... ..... ..#.. .#... ...#. ..#.. ##### .....",
      ".###. ..... ..... ..... .#... .#... ...#. ##### ..... .....",
      "..... ..... ..#.. ..... #.... ..#.. ..#.. ..#.. ##### .....",
      "..... ..#.. ..#.. ..#.. #.... ...#. .#... ..#.. ..... .....",
      "..... ..... .#... ..... ..... ..... ..... ..... ..... .....",
      "..... ..... ..... ..... ..... ..... ..... ..... ..... ....."}},
    // Any other character: an empty box, cap height.
    {"\x7f",
     {"#####", "#...#", "#...#", "#...#", "#...#", "#...#", "#####", ".....", "....."}},
};
// clang-format on

}  // namespace

std::array<std::string_view, k_glyph_height> glyph_rows(char c) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    for (const GlyphSheet& sheet : k_sheets) {
        const size_t i = sheet.chars.find(c);
        if (i == std::string_view::npos) continue;
        std::array<std::string_view, k_glyph_height> rows;
        for (int r = 0; r < k_glyph_height; ++r)
            rows[r] = sheet.rows[r].substr(i * k_glyph_advance, k_glyph_width);
        return rows;
    }
    return glyph_rows('\x7f');
}

int text_width(std::string_view text, int scale) {
    if (text.empty()) return 0;
    return (static_cast<int>(text.size()) * k_glyph_advance - 1) * scale;
}

void draw_text(Srgb8Image& image, int x, int y, std::string_view text, int scale,
               std::array<uint8_t, 3> rgb, ColumnRange clip) {
    const int x0 = std::max(clip.x0, 0), x1 = std::min(clip.x1, image.width);
    for (size_t k = 0; k < text.size(); ++k) {
        const std::array<std::string_view, k_glyph_height> rows = glyph_rows(text[k]);
        const int left = x + static_cast<int>(k) * k_glyph_advance * scale;
        for (int r = 0; r < k_glyph_height; ++r)
            for (int c = 0; c < k_glyph_width; ++c) {
                if (rows[r][c] != '#') continue;
                // One font pixel: a scale × scale square, clipped.
                for (int py = y + r * scale; py < y + (r + 1) * scale; ++py)
                    for (int px = left + c * scale; px < left + (c + 1) * scale; ++px)
                        if (py >= 0 && py < image.height && px >= x0 && px < x1)
                            std::copy(rgb.begin(), rgb.end(), image.row(py) + 3 * px);
            }
    }
}

}  // namespace hikari
