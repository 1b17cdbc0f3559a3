#include "hikari/io/images/svg_write.h"

#include <gtest/gtest.h>

#include <regex>

#include "../temp_dir.h"

namespace hikari {
namespace {

LineDrawing two_lines() {
    LineDrawing d;
    d.width = 320;
    d.height = 200;
    d.line_width = 1.5f;
    d.background = Vec3(0.0f, 0.0f, 1.0f);
    LineSegment s;
    s.a = {10.25f, 20};
    s.b = {300, 180.5f};
    s.color = Vec3(1.0f, 0.2158605f, 0.0f);  // sRGB 255, 128, 0
    d.segments.push_back(s);
    s.a = {0, 0};
    s.b = {5, 5};
    s.color = Vec3(0.0f);
    d.segments.push_back(s);
    return d;
}

TEST(SvgWrite, LinesInPixelCoordinatesWithSrgbColours) {
    const std::string svg = svg_document(two_lines());
    EXPECT_NE(svg.find(R"(viewBox="0 0 320 200")"), std::string::npos) << svg;
    EXPECT_NE(svg.find(R"(<rect width="320" height="200" fill="#0000ff"/>)"), std::string::npos);
    EXPECT_NE(svg.find(R"(stroke-width="1.5")"), std::string::npos);
    EXPECT_NE(
        svg.find(R"(<line x1="10.250" y1="20.000" x2="300.000" y2="180.500" stroke="#ff8000"/>)"),
        std::string::npos)
        << svg;
    const std::regex line("<line ");
    EXPECT_EQ(std::distance(std::sregex_iterator(svg.begin(), svg.end(), line), {}), 2);
    EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
}

TEST(SvgWrite, WritesTheWholeFile) {
    testing::TempDir dir;
    write_svg(dir / "d.svg", two_lines());
    EXPECT_EQ(testing::read_text(dir / "d.svg"), svg_document(two_lines()));
    EXPECT_EQ(dir.entry_count(), 1u);
}

TEST(SvgWrite, RecognisesSvgPaths) {
    EXPECT_TRUE(is_svg_path("a/b.svg"));
    EXPECT_TRUE(is_svg_path("B.SVG"));
    EXPECT_FALSE(is_svg_path("b.png"));
    EXPECT_FALSE(is_svg_path("svg"));
}

}  // namespace
}  // namespace hikari
