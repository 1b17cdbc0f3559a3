#include "hikari/io/png_write.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>

#include "hikari/core/color.h"
#include "hikari/core/rng.h"
#include "hikari/core/srgb8_encoder.h"
#include "hikari/io/image_read.h"
#include "hikari/io/image_write.h"
#include "temp_dir.h"

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

TEST(PngWrite, ChunksCarryValidCrcsAndTheStreamValidAdler) {
    const std::vector<uint8_t> png = encode_png(encode_srgb8(test_card(64, 100)));
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
    // zlib's uncompress checks the Adler-32 trailer; 100 rows of 1 + 64·3 bytes come out.
    std::vector<uint8_t> raw(100 * (1 + 64 * 3));
    uLongf raw_size = raw.size();
    EXPECT_EQ(uncompress(raw.data(), &raw_size, zlib_stream.data(), zlib_stream.size()), Z_OK);
    EXPECT_EQ(raw_size, raw.size());
}

}  // namespace
}  // namespace hikari
