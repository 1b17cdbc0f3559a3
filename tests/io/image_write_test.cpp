#include "hikari/io/image_write.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "hikari/core/error.h"
#include "hikari/core/srgb8_encoder.h"
#include "temp_dir.h"

namespace hikari {
namespace {

using testing::read_text;
using testing::TempDir;
using testing::write_text;

/// A 2x2 image with four distinct pixels: top row (0.1, 0.2), bottom row (0.3, 0.4).
Image two_by_two() {
    Image image(2, 2);
    image.at(0, 0) = Vec3(0.1f);
    image.at(1, 0) = Vec3(0.2f);
    image.at(0, 1) = Vec3(0.3f);
    image.at(1, 1) = Vec3(0.4f);
    return image;
}

float float_at(const std::string& bytes, size_t offset) {
    float v = 0;
    std::memcpy(&v, bytes.data() + offset, 4);  // the test host is little-endian like the file
    return v;
}

TEST(ImageWrite, ExtensionsAreCaseInsensitive) {
    EXPECT_TRUE(is_supported_image_extension("a.png"));
    EXPECT_TRUE(is_supported_image_extension("dir/a.PNG"));
    EXPECT_TRUE(is_supported_image_extension("a.Exr"));
    EXPECT_TRUE(is_supported_image_extension("a.pfm"));
    EXPECT_TRUE(is_supported_image_extension("a.ppm"));
    EXPECT_FALSE(is_supported_image_extension("a.jpg"));
    EXPECT_FALSE(is_supported_image_extension("a.bmp"));
    EXPECT_FALSE(is_supported_image_extension("png"));
}

TEST(ImageWrite, UnknownExtensionListsSupportedOnes) {
    TempDir dir;
    try {
        write_image(dir / "a.bmp", two_by_two());
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("a.bmp"), std::string::npos) << message;
        EXPECT_NE(message.find(".png, .ppm, .pfm, .exr"), std::string::npos) << message;
    }
    EXPECT_EQ(dir.entry_count(), 0u);
}

TEST(ImageWrite, PfmStoresBottomRowFirstLittleEndian) {
    TempDir dir;
    write_image(dir / "a.pfm", two_by_two());
    const std::string bytes = read_text(dir / "a.pfm");
    const std::string header = "PF\n2 2\n-1.0\n";
    ASSERT_EQ(bytes.size(), header.size() + 2 * 2 * 3 * 4);
    EXPECT_EQ(bytes.substr(0, header.size()), header);
    EXPECT_EQ(float_at(bytes, header.size()), 0.3f);       // first stored = bottom-left
    EXPECT_EQ(float_at(bytes, header.size() + 12), 0.4f);  // bottom-right
    EXPECT_EQ(float_at(bytes, header.size() + 24), 0.1f);  // then top-left
}

TEST(ImageWrite, PpmIsBinaryP6Srgb) {
    TempDir dir;
    Image image(2, 1);
    image.at(0, 0) = {0.0f, 1.0f, 2.0f};  // 2.0 clamps to 255
    image.at(1, 0) = Vec3(0.5f);          // linear 0.5 is sRGB 188
    write_image(dir / "a.ppm", image);
    const std::string bytes = read_text(dir / "a.ppm");
    const std::string header = "P6\n2 1\n255\n";
    ASSERT_EQ(bytes.size(), header.size() + 6);
    EXPECT_EQ(bytes.substr(0, header.size()), header);
    EXPECT_EQ(static_cast<uint8_t>(bytes[header.size() + 0]), 0);
    EXPECT_EQ(static_cast<uint8_t>(bytes[header.size() + 1]), 255);
    EXPECT_EQ(static_cast<uint8_t>(bytes[header.size() + 2]), 255);
    EXPECT_EQ(static_cast<uint8_t>(bytes[header.size() + 3]), 188);
}

TEST(ImageWrite, PngAndExrHaveTheirMagicNumbers) {
    TempDir dir;
    write_image(dir / "a.png", two_by_two());
    write_image(dir / "a.exr", two_by_two());
    EXPECT_EQ(read_text(dir / "a.png").substr(0, 8), "\x89PNG\r\n\x1a\n");
    EXPECT_EQ(read_text(dir / "a.exr").substr(0, 4), "\x76\x2f\x31\x01");
}

TEST(ImageWrite, Srgb8ImagesWriteTheSameBytesAsTheLinearImage) {
    TempDir dir;
    Image image(37, 70);  // more rows than one PNG band
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            image.at(x, y) = {static_cast<float>(x) / 36.0f, static_cast<float>(y % 9) / 8.0f,
                              static_cast<float>((x * y) % 5) * 0.3f};
    const Srgb8Image srgb8 = encode_srgb8(image);
    for (const char* ext : {".png", ".ppm"}) {
        write_image(dir / (std::string("linear") + ext), image);
        write_image(dir / (std::string("srgb8") + ext), srgb8);
        EXPECT_EQ(read_text(dir / (std::string("linear") + ext)),
                  read_text(dir / (std::string("srgb8") + ext)))
            << ext;
    }
    // Float formats need the linear image; malformed 8-bit images are refused like float ones.
    EXPECT_THROW(write_image(dir / "a.pfm", srgb8), InputError);
    Srgb8Image torn = srgb8;
    torn.bytes.pop_back();
    EXPECT_THROW(write_image(dir / "torn.png", torn), InputError);
    EXPECT_FALSE(std::filesystem::exists(dir / "a.pfm"));
    EXPECT_FALSE(std::filesystem::exists(dir / "torn.png"));
}

TEST(ImageWrite, MissingDirectoryLeavesNothingBehind) {
    TempDir dir;
    for (const char* name : {"a.png", "a.ppm", "a.pfm", "a.exr"}) {
        EXPECT_THROW(write_image(dir / "missing" / name, two_by_two()), InputError) << name;
    }
    EXPECT_EQ(dir.entry_count(), 0u);
}

TEST(ImageWrite, FailedWriteKeepsExistingTarget) {
    TempDir dir;
    write_text(dir / "a.png", "previous render");
    EXPECT_THROW(write_image(dir / "a.png", Image()), InputError);  // empty image
    EXPECT_EQ(read_text(dir / "a.png"), "previous render");
    EXPECT_EQ(dir.entry_count(), 1u);
}

}  // namespace
}  // namespace hikari
