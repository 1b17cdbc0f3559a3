#include "hikari/io/images/png_write.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>

#include "../temp_dir.h"
#include "hikari/core/color.h"
#include "hikari/core/rng.h"
#include "hikari/core/srgb8_encoder.h"
#include "hikari/io/images/image_read.h"
#include "hikari/io/images/image_write.h"

namespace hikari {
namespace {

using testing::TempDir;

/// Smooth ramps, flat areas (long runs after filtering), noise and out-of-range values, over
/// more rows than one band so that several bands and IDAT chunks are written.
Image test_card(int width, int height) {
    Image image(width, height);
    Pcg32 rng(3, 5);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            Vec3& p = image.at(x, y);
            if (y < height / 3)
                p = Vec3(static_cast<float>(x) / width, static_cast<float>(y) / height, 0.5f);
            else if (y < 2 * height / 3)
                p = Vec3(x < width / 2 ? 0.2f : 0.8f);
            else
                p = Vec3(rng.next_float(), rng.next_float() * 2.0f - 0.5f, -1.0f);
        }
    image.at(0, 0) = Vec3(NAN, INFINITY, 1e-7f);
    return image;
}

/// The image read back has every sample at its 8-bit sRGB code.
void expect_round_trip(const Image& image, const TempDir& dir) {
    write_image(dir / "a.png", image);
    const Image back = read_image(dir / "a.png");
    ASSERT_EQ(back.width, image.width);
    ASSERT_EQ(back.height, image.height);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            ASSERT_EQ(linear_to_srgb8(back.pixels[i][c]), linear_to_srgb8(image.pixels[i][c]))
                << "pixel " << i << " channel " << c;
}

TEST(PngWrite, RoundTripsThroughTheReader) {
    TempDir dir;
    expect_round_trip(test_card(300, 101), dir);
}

TEST(PngWrite, RoundTripsOddSizes) {
    TempDir dir;
    expect_round_trip(test_card(1, 1), dir);
    expect_round_trip(test_card(1, 70), dir);
    expect_round_trip(test_card(517, 2), dir);
}

/// Checks every chunk's CRC of `png` and inflates its zlib stream with zlib's uncompress, which
/// checks the Adler-32 trailer; `raw_size` bytes (rows with their filter bytes) must come out.
void expect_valid_chunks_and_stream(const std::vector<uint8_t>& png, size_t raw_size) {
    ASSERT_GT(png.size(), 8u);
    std::vector<uint8_t> zlib_stream;
    size_t at = 8;
    while (at + 12 <= png.size()) {
        const uint32_t length = uint32_t{png[at]} << 24 | uint32_t{png[at + 1]} << 16 |
                                uint32_t{png[at + 2]} << 8 | png[at + 3];
        const uint8_t* type = png.data() + at + 4;
        const uint8_t* crc = type + 4 + length;
        const auto want = static_cast<uint32_t>(crc32(0L, type, 4 + length));
        EXPECT_EQ(want,
                  uint32_t{crc[0]} << 24 | uint32_t{crc[1]} << 16 | uint32_t{crc[2]} << 8 | crc[3]);
        if (std::equal(type, type + 4, "IDAT"))
            zlib_stream.insert(zlib_stream.end(), type + 4, crc);
        at += 12 + length;
    }
    EXPECT_EQ(at, png.size());
    std::vector<uint8_t> raw(raw_size);
    uLongf inflated = raw.size();
    EXPECT_EQ(uncompress(raw.data(), &inflated, zlib_stream.data(), zlib_stream.size()), Z_OK);
    EXPECT_EQ(inflated, raw.size());
}

TEST(PngWrite, ChunksCarryValidCrcsAndTheStreamValidAdler) {
    // 100 rows of 1 + 64·3 bytes.
    expect_valid_chunks_and_stream(encode_png(encode_srgb8(test_card(64, 100))),
                                   100 * (1 + 64 * 3));
}

TEST(PngWrite, AdlerHoldsOverLongRowsOfLargeBytes) {
    // Noise filters to bytes up to 255, and rows of 9004 bytes run past the 5552 bytes between
    // the checksum's modulo reductions: the sums' worst case.
    for (const int width : {3001, 3000, 11}) {
        Srgb8Image image(width, 70);
        Pcg32 rng(static_cast<uint64_t>(width), 7);
        for (uint8_t& byte : image.bytes) byte = static_cast<uint8_t>(rng.next_u32());
        expect_valid_chunks_and_stream(encode_png(image),
                                       70 * (1 + static_cast<size_t>(width) * 3));
    }
}

TEST(PngWrite, SixteenBitSamplesAreTheRoundedCurveBigEndian) {
    Image image(2, 1);
    image.at(0, 0) = {0.0f, 1.0f, 0.5f};
    image.at(1, 0) = {0.2f, NAN, -3.0f};
    const Srgb16Image srgb16 = encode_srgb16(image);
    const std::vector<uint8_t> want = {0x00, 0x00, 0xFF, 0xFF, 0xBC, 0x40,   // 48192
                                       0x7C, 0x0A, 0x00, 0x00, 0x00, 0x00};  // 31754
    EXPECT_EQ(srgb16.bytes, want);
}

TEST(PngWrite, SixteenBitStreamsAreValidAndRoundTrip) {
    // Rows of 6 bytes per pixel, over several bands; the filters pair bytes a pixel apart.
    for (const int width : {1, 2, 57}) {
        const Image card = test_card(width, 75);
        const Srgb16Image srgb16 = encode_srgb16(card);
        const std::vector<uint8_t> png = encode_png(srgb16);
        expect_valid_chunks_and_stream(png, 75 * (1 + static_cast<size_t>(width) * 6));
        EXPECT_EQ(png[24], 16) << "IHDR bit depth";
        TempDir dir;
        write_image(dir / "a.png", card, ImageWriteSettings{16});
        const Image back = read_image(dir / "a.png");
        ASSERT_EQ(back.width, width);
        for (size_t i = 0; i < card.pixels.size(); ++i)
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(std::lround(linear_to_srgb(back.pixels[i][c]) * 65535.0f),
                          std::lround(linear_to_srgb(card.pixels[i][c]) * 65535.0f))
                    << "width " << width << " pixel " << i << " channel " << c;
    }
}

TEST(PngWrite, EverySimdLevelWritesTheSameBytes) {
    // Rows shorter than one 16-byte step, rows that end mid-step, and rows long enough for the
    // checksum's reductions; smooth ramps, flat runs and noise (test_card), then pure noise.
    for (const int width : {1, 5, 6, 11, 64, 517, 3001}) {
        const Srgb8Image card = encode_srgb8(test_card(width, 75));
        Srgb8Image noise(width, 40);
        Pcg32 rng(static_cast<uint64_t>(width), 11);
        for (uint8_t& byte : noise.bytes) byte = static_cast<uint8_t>(rng.next_u32());
        for (const Srgb8Image* image : {&card, static_cast<const Srgb8Image*>(&noise)}) {
            const std::vector<uint8_t> reference = encode_png(*image, SimdLevel::portable);
            for (const SimdLevel level : supported_simd_levels())
                EXPECT_EQ(encode_png(*image, level), reference)
                    << simd_level_name(level) << ", width " << width;
        }
    }
}

}  // namespace
}  // namespace hikari
