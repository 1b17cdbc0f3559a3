#include "hikari/io/images/image_write.h"

#include <gtest/gtest.h>
#include <stb/stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>

#include "../temp_dir.h"
#include "hikari/core/color.h"
#include "hikari/core/error.h"
#include "hikari/core/srgb8_encoder.h"
#include "hikari/io/images/image_read.h"

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
    EXPECT_TRUE(is_supported_image_extension("a.jpg"));
    EXPECT_TRUE(is_supported_image_extension("a.JPEG"));
    EXPECT_TRUE(is_supported_image_extension("a.hdr"));
    EXPECT_TRUE(is_supported_image_extension("a.xlsx"));
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
        EXPECT_NE(message.find(k_writable_image_extensions), std::string::npos) << message;
        EXPECT_NE(message.find(".jpg"), std::string::npos) << message;
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

TEST(ImageWrite, LinearEncodingIs255TimesTheValueAsTheLecturesCode) {
    TempDir dir;
    Image image(3, 1);
    image.at(0, 0) = {0.8f, 0.3f, 0.2f};  // the stage-1 sphere: (204, 77, 51), sRGB (231, 149, 124)
    image.at(1, 0) = {0.5f, 2.0f, -1.0f};   // clamped to [0, 1]
    image.at(2, 0) = {NAN, 1e-3f, 0.998f};  // NaN as 0
    for (const int bits : {8, 16}) {
        SCOPED_TRACE(bits);
        write_image(dir / "a.ppm", image, ImageWriteSettings{bits, SampleEncoding::linear});
        const std::string bytes = read_text(dir / "a.ppm");
        const float max_code = bits == 8 ? 255.0f : 65535.0f;
        const size_t body = bytes.size() - image.pixels.size() * 3 * (bits / 8);
        for (size_t i = 0; i < 9; ++i) {
            const float v = image.pixels[i / 3][static_cast<int>(i % 3)];
            const long expected =
                std::isnan(v) ? 0 : std::lround(std::clamp(v, 0.0f, 1.0f) * max_code);
            const auto* b = reinterpret_cast<const uint8_t*>(bytes.data() + body);
            const long got = bits == 8 ? b[i] : (long{b[2 * i]} << 8) | b[2 * i + 1];
            EXPECT_EQ(got, expected) << "sample " << i;
        }
    }
    const Srgb8Image linear = encode_linear8(image);
    EXPECT_EQ(linear.bytes[0], 204);
    EXPECT_EQ(linear.bytes[1], 77);
    EXPECT_EQ(linear.bytes[2], 51);
    EXPECT_EQ(linear_to_srgb8(0.8f), 231);  // what the default writes for the same value
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

/// Smooth ramps (what JPEG keeps well) from black to white, with values past 1 that clamp.
Image gradient(int width, int height) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.at(x, y) = {
                static_cast<float>(x) / static_cast<float>(width - 1),
                static_cast<float>(y) / static_cast<float>(height - 1),
                1.2f * static_cast<float>(x + y) / static_cast<float>(width + height)};
    return image;
}

/// The 8- or 16-bit RGB samples stb_image decodes from `file` (a PNG, JPEG or PPM).
template <class Sample>
std::vector<Sample> decode_samples(const std::string& file, int width, int height) {
    int w = 0, h = 0, channels = 0;
    const auto* data = reinterpret_cast<const stbi_uc*>(file.data());
    const int size = static_cast<int>(file.size());
    Sample* samples = nullptr;
    if constexpr (sizeof(Sample) == 2)
        samples = stbi_load_16_from_memory(data, size, &w, &h, &channels, 3);
    else
        samples = stbi_load_from_memory(data, size, &w, &h, &channels, 3);
    EXPECT_NE(samples, nullptr) << stbi_failure_reason();
    if (!samples) return {};
    EXPECT_EQ(w, width);
    EXPECT_EQ(h, height);
    std::vector<Sample> out(samples, samples + 3 * static_cast<size_t>(width) * height);
    stbi_image_free(samples);
    return out;
}

TEST(ImageWrite, JpegDecodesCloseToTheSource) {
    TempDir dir;
    const Image image = gradient(48, 40);  // several 8x8 blocks, and edges of partial ones
    write_image(dir / "a.jpg", image);
    const std::string bytes = read_text(dir / "a.jpg");
    ASSERT_GE(bytes.size(), 4u);
    EXPECT_EQ(bytes.substr(0, 3), "\xFF\xD8\xFF");  // SOI, then a marker
    const std::vector<uint8_t> decoded = decode_samples<uint8_t>(bytes, 48, 40);
    const Srgb8Image expected = encode_srgb8(image);
    ASSERT_EQ(decoded.size(), expected.bytes.size());
    int worst = 0, total = 0;
    for (size_t i = 0; i < decoded.size(); ++i) {
        const int error = std::abs(int{decoded[i]} - int{expected.bytes[i]});
        worst = std::max(worst, error);
        total += error;
    }
    // Quality 95 on smooth ramps: a few levels at worst, about one on average.
    EXPECT_LE(worst, 8);
    EXPECT_LE(static_cast<double>(total) / static_cast<double>(decoded.size()), 1.5);
    // The 8-bit film's bytes give the same file, and .jpeg is the same format.
    write_image(dir / "b.jpeg", expected);
    EXPECT_EQ(read_text(dir / "b.jpeg"), bytes);
}

TEST(ImageWrite, HdrRoundTripsWithinRgbePrecision) {
    TempDir dir;
    Image image(9, 7);  // past 1 (unclamped), small, and channels far apart in size
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            image.at(x, y) = {std::ldexp(1.0f + 0.1f * x, y - 3), 0.37f * (x + 1), 100.0f + y};
    image.at(0, 0) = {0.0f, -1.0f, NAN};  // no sign or NaN in RGBE: 0
    write_image(dir / "a.hdr", image);
    EXPECT_EQ(read_text(dir / "a.hdr").substr(0, 10), "#?RADIANCE");
    const Image back = read_image(dir / "a.hdr");
    ASSERT_EQ(back.width, image.width);
    ASSERT_EQ(back.height, image.height);
    EXPECT_EQ(back.at(0, 0), Vec3(0.0f));
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            if (x == 0 && y == 0) continue;
            // The shared exponent is the largest channel's: each channel is truncated to a
            // multiple of 2^(e − 8), under 1/128 of the largest channel (which is ≥ 2^(e − 1)).
            const Vec3 p = image.at(x, y);
            const float largest = std::max({p.x, p.y, p.z});
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(back.at(x, y)[c], p[c], largest / 128.0f) << x << "," << y << " " << c;
        }
}

TEST(ImageWrite, SixteenBitPngHoldsTheRoundedCurve) {
    TempDir dir;
    Image image(3, 2);
    image.at(0, 0) = {0.0f, 1.0f, 2.0f};  // black, white, clamped
    image.at(1, 0) = {0.5f, 0.2f, 0.001f};
    image.at(2, 0) = {0.0031308f, 1e-6f, 0.9f};
    image.at(0, 1) = {NAN, -1.0f, 0.75f};
    image.at(1, 1) = {0.3f, 0.6f, 0.05f};
    image.at(2, 1) = {0.01f, 0.1f, 0.99f};
    write_image(dir / "a.png", image, ImageWriteSettings{16});
    const std::string bytes = read_text(dir / "a.png");
    ASSERT_GT(bytes.size(), 33u);
    EXPECT_EQ(static_cast<uint8_t>(bytes[24]), 16);  // IHDR bit depth
    EXPECT_EQ(static_cast<uint8_t>(bytes[25]), 2);   // colour type RGB
    const std::vector<uint16_t> samples = decode_samples<uint16_t>(bytes, 3, 2);
    ASSERT_EQ(samples.size(), 18u);
    for (size_t i = 0; i < 6; ++i)
        for (int c = 0; c < 3; ++c) {
            const auto want =
                static_cast<uint16_t>(std::lround(linear_to_srgb(image.pixels[i][c]) * 65535.0f));
            EXPECT_EQ(samples[3 * i + c], want) << "pixel " << i << " channel " << c;
        }
    EXPECT_EQ(samples[0], 0);
    EXPECT_EQ(samples[1], 65535);
    EXPECT_EQ(samples[2], 65535);
    // Linear 0.5 is sRGB 0.735357: 48191.6 rounds to 48192, where the 8-bit code 188 widened
    // (188 · 257) would be 48316.
    EXPECT_EQ(samples[3], 48192);
}

TEST(ImageWrite, SixteenBitPpmHasMaxval65535AndBigEndianSamples) {
    TempDir dir;
    Image image(2, 1);
    image.at(0, 0) = {0.0f, 1.0f, 0.5f};
    image.at(1, 0) = {0.2f, 3.0f, 0.01f};
    write_image(dir / "a.ppm", image, ImageWriteSettings{16});
    const std::string bytes = read_text(dir / "a.ppm");
    const std::string header = "P6\n2 1\n65535\n";
    ASSERT_EQ(bytes.size(), header.size() + 12);
    EXPECT_EQ(bytes.substr(0, header.size()), header);
    const auto sample = [&](size_t i) {
        return static_cast<uint16_t>(static_cast<uint8_t>(bytes[header.size() + 2 * i]) << 8 |
                                     static_cast<uint8_t>(bytes[header.size() + 2 * i + 1]));
    };
    EXPECT_EQ(sample(0), 0);
    EXPECT_EQ(sample(1), 65535);
    EXPECT_EQ(sample(2), 48192);
    EXPECT_EQ(sample(4), 65535);
    // The reader's 16-bit path decodes it back to within half a 16-bit step.
    const Image back = read_image(dir / "a.ppm");
    EXPECT_NEAR(linear_to_srgb(back.at(1, 0).x), linear_to_srgb(0.2f), 0.5f / 65535.0f);
}

TEST(ImageWrite, SixteenBitsOnlyForPngAndPpm) {
    TempDir dir;
    EXPECT_TRUE(supports_bit_depth("a.png", 16));
    EXPECT_TRUE(supports_bit_depth("a.PPM", 16));
    EXPECT_TRUE(supports_bit_depth("a.exr", 8));
    EXPECT_FALSE(supports_bit_depth("a.png", 12));
    for (const char* name : {"a.jpg", "a.pfm", "a.exr", "a.hdr", "a.xlsx"}) {
        EXPECT_FALSE(supports_bit_depth(name, 16)) << name;
        EXPECT_THROW(write_image(dir / name, two_by_two(), ImageWriteSettings{16}), InputError)
            << name;
    }
    EXPECT_THROW(write_image(dir / "a.png", two_by_two(), ImageWriteSettings{12}), InputError);
    EXPECT_EQ(dir.entry_count(), 0u);
}

TEST(ImageWrite, MissingDirectoryLeavesNothingBehind) {
    TempDir dir;
    for (const char* name : {"a.png", "a.ppm", "a.pfm", "a.exr", "a.jpg", "a.hdr"}) {
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
