#include "hikari/io/files/frame_pattern.h"

#include <gtest/gtest.h>

namespace {

using namespace hikari;

std::string name_of(const std::string& pattern, int frame) {
    std::string why;
    const std::optional<FramePattern> p = parse_frame_pattern(pattern, why);
    EXPECT_TRUE(p) << pattern << ": " << why;
    return p ? p->file_name(frame) : std::string();
}

TEST(FramePattern, PadsTheFrameNumberAsPrintfDoes) {
    EXPECT_EQ(name_of("out/frame_%04d.png", 7), "out/frame_0007.png");
    EXPECT_EQ(name_of("out/frame_%04d.png", 12345), "out/frame_12345.png");
    EXPECT_EQ(name_of("f%d.exr", 42), "f42.exr");
    EXPECT_EQ(name_of("%03d", 5), "005");
    EXPECT_EQ(name_of("100%%_%02d.png", 3), "100%_03.png");
}

TEST(FramePattern, RefusesNamesWithoutExactlyOneFrameNumber) {
    for (const char* bad :
         {"frame.png", "f_%04d_%04d.png", "f_%s.png", "f_%4d.png", "f_%", "100%%.png"}) {
        std::string why;
        EXPECT_FALSE(parse_frame_pattern(bad, why)) << bad;
        EXPECT_FALSE(why.empty()) << bad;
    }
}

}  // namespace
