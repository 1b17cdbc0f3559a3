// The label font: every glyph well formed and its own, drawing clipped to its columns.

#include <set>
#include <string>

#include <gtest/gtest.h>

#include "hikari/frame/bitmap_font.h"

namespace hikari {
namespace {

const std::string k_covered = "abcdefghijklmnopqrstuvwxyz0123456789-.,:/()+= ";

std::string joined(const std::array<std::string_view, k_glyph_height>& rows) {
    std::string s;
    for (std::string_view r : rows) s += std::string(r) + "|";
    return s;
}

TEST(BitmapFont, EveryGlyphIsFiveByNineOfInkOrNone) {
    for (const char c : k_covered + "\x7f~") {
        for (std::string_view row : glyph_rows(c)) {
            ASSERT_EQ(row.size(), size_t(k_glyph_width)) << c;
            for (const char p : row) EXPECT_TRUE(p == '#' || p == '.') << c << ": " << row;
        }
    }
}

TEST(BitmapFont, EveryCoveredCharacterHasItsOwnGlyph) {
    // A banner column out of step would give two characters one glyph, or a box.
    std::set<std::string> seen;
    const std::string box = joined(glyph_rows('~'));
    for (const char c : k_covered) {
        const std::string g = joined(glyph_rows(c));
        EXPECT_TRUE(seen.insert(g).second) << "'" << c << "' repeats another glyph";
        EXPECT_NE(g, box) << c;
    }
    EXPECT_EQ(joined(glyph_rows('Q')), joined(glyph_rows('q')));
    EXPECT_EQ(glyph_rows('i')[0], "..#..");  // the dot
    EXPECT_EQ(glyph_rows('g')[8], ".###.");  // a descender
}

TEST(BitmapFont, TextWidthIsTheAdvancesLessTheLastSpace) {
    EXPECT_EQ(text_width("", 2), 0);
    EXPECT_EQ(text_width("a", 1), 5);
    EXPECT_EQ(text_width("zbuffer", 2), (7 * 6 - 1) * 2);
}

TEST(BitmapFont, DrawingInksTheGlyphAndStaysInsideItsColumns) {
    Srgb8Image image(20, 20);
    std::fill(image.bytes.begin(), image.bytes.end(), uint8_t{255});
    draw_text(image, 1, 1, "l", 2, {0, 0, 0}, {0, 20});
    const auto ink = [&](int x, int y) { return image.row(y)[3 * x] == 0; };
    // 'l' row 0 is ".##..": font pixels 1 and 2, picture columns 3 to 6 of rows 1 and 2.
    EXPECT_FALSE(ink(2, 1));
    EXPECT_TRUE(ink(3, 1) && ink(6, 2));
    EXPECT_FALSE(ink(7, 1));
    Srgb8Image clipped(20, 20);
    std::fill(clipped.bytes.begin(), clipped.bytes.end(), uint8_t{255});
    draw_text(clipped, 0, 0, "mmmm", 1, {0, 0, 0}, {4, 9});
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 20; ++x)
            if (x < 4 || x >= 9) EXPECT_EQ(clipped.row(y)[3 * x], 255) << x << "," << y;
}

}  // namespace
}  // namespace hikari
