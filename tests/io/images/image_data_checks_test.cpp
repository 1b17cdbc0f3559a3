// Image headers checked against the bytes a file holds before decoding (issue 41, classes 5 and
// 7): JPEGs with headers but no scans, short scans, scan bombs; HDR files whose pixel data stops
// short. The hostile files are a few bytes, made here.

#include "hikari/io/images/image_data_checks.h"

#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include "../../support/input_error.h"
#include "../temp_dir.h"
#include "hikari/core/memory_budget.h"
#include "hikari/io/images/image_read.h"
#include "hikari/io/images/image_write.h"

namespace hikari {
namespace {

using testing::input_error_of;
using testing::TempDir;

std::string u16(unsigned v) { return {static_cast<char>(v >> 8), static_cast<char>(v & 255)}; }

/// A JPEG frame header (SOF0 baseline or SOF2 progressive) of `w` × `h`, three components
/// sampled 1×1.
std::string sof(bool progressive, unsigned w, unsigned h) {
    return std::string("\xFF") + (progressive ? "\xC2" : "\xC0") + u16(17) + "\x08" + u16(h) +
           u16(w) + std::string("\x03\x01\x11\x00\x02\x11\x00\x03\x11\x00", 10);
}

/// A scan header (SOS) over all three components; `dc` scans start at coefficient 0.
std::string sos(bool dc) {
    return std::string("\xFF\xDA", 2) + u16(12) + std::string("\x03\x01\x00\x02\x11\x03\x11", 7) +
           (dc ? std::string("\x00\x3F\x00", 3) : std::string("\x01\x3F\x00", 3));
}

const std::string k_soi("\xFF\xD8", 2), k_eoi("\xFF\xD9", 2);

TEST(JpegData, HeadersWithoutScanAreTruncated) {
    const std::string jpeg = k_soi + sof(false, 16000, 16000) + k_eoi;
    EXPECT_EQ(input_error_of([&] { check_jpeg_data("a.jpg", jpeg); }),
              "a.jpg: truncated JPEG: headers but no scan data (no SOS segment)");
}

TEST(JpegData, ScanShorterThanOneBitPerBlockIsTruncated) {
    // 1000 × 1000, three components: 3 × 125² blocks need 5860 bytes at one bit each.
    const std::string jpeg =
        k_soi + sof(false, 1000, 1000) + sos(true) + std::string(20, '\x12') + k_eoi;
    EXPECT_EQ(input_error_of([&] { check_jpeg_data("a.jpg", jpeg); }),
              "a.jpg: truncated JPEG: scan 1 holds 20 bytes of data, its 46875 blocks need at "
              "least 5860");
}

TEST(JpegData, SegmentPastTheEndIsTruncated) {
    const std::string jpeg = k_soi + sof(false, 8, 8).substr(0, 9);
    EXPECT_NE(input_error_of([&] { check_jpeg_data("a.jpg", jpeg); }).find("runs past the end"),
              std::string::npos);
}

TEST(JpegData, MoreScansThanTheLimitAreRefused) {
    // AC scans need no bits per block (an end-of-band run covers them), so each can be 2 bytes.
    std::string jpeg = k_soi + sof(true, 8, 8) + sos(true) + std::string(8, '\x12');
    for (int i = 0; i < k_max_jpeg_scans + 1; ++i) jpeg += sos(false) + "\x12\x34";
    EXPECT_EQ(input_error_of([&] { check_jpeg_data("a.jpg", jpeg + k_eoi); }),
              "a.jpg: JPEG has more than 500 scans");
}

TEST(JpegData, ScansWalkingTooManyBlocksAreRefused) {
    // 8192² in three components: 3 × 2^20 blocks a scan; the DC scan holds its 2^18 + bytes, and
    // 42 nearly empty AC scans then walk past 2^27 blocks.
    std::string jpeg = k_soi + sof(true, 8192, 8192) + sos(true) + std::string(3 << 17, '\x12');
    for (int i = 0; i < 42; ++i) jpeg += sos(false) + "\x12\x34";
    const std::string error = input_error_of([&] { check_jpeg_data("a.jpg", jpeg + k_eoi); });
    EXPECT_NE(error.find("a.jpg: JPEG's 43 scans walk more than 134217728 blocks of its 8192x8192 "
                         "image"),
              std::string::npos)
        << error;
}

/// A DHT segment (T.81 B.2.4.2) of one AC table whose 16 code counts are all `count`.
std::string huffman_table(unsigned count) {
    const size_t codes = 16 * size_t(count);
    return std::string("\xFF\xC4", 2) + u16(unsigned(2 + 17 + codes)) + "\x10" +
           std::string(16, static_cast<char>(count)) + std::string(codes, '\x01');
}

TEST(JpegData, HuffmanTableOfMoreThan256CodesIsRefusedBeforeDecoding) {
    // 16 × 20 = 320 codes: stb_image's header pass (even stbi_info) would write past its table.
    const std::string jpeg =
        k_soi + huffman_table(20) + sof(false, 8, 8) + sos(true) + std::string(8, '\x12') + k_eoi;
    EXPECT_EQ(input_error_of([&] { check_jpeg_data("a.jpg", jpeg); }),
              "a.jpg: corrupt JPEG: a Huffman table at byte 6 has 320 codes (at most 256)");
    TempDir dir;
    testing::write_text(dir / "a.jpg", jpeg);
    EXPECT_NE(input_error_of([&] { read_image(dir / "a.jpg"); }).find("has 320 codes"),
              std::string::npos);
    // 16 × 16 = 256 codes is the most a table may hold: the walk lets it by.
    check_jpeg_data("a.jpg", k_soi + huffman_table(16) + sof(false, 8, 8) + sos(true) +
                                 std::string(8, '\x12') + k_eoi);
}

TEST(JpegData, WrittenJpegPassesAndDecodes) {
    TempDir dir;
    Image image(40, 24, Vec3(0.25f, 0.5f, 0.75f));
    write_image(dir / "a.jpg", image);
    const Image back = read_image(dir / "a.jpg");
    EXPECT_EQ(back.width, 40);
    EXPECT_NEAR(back.at(20, 12).y, 0.5f, 0.02f);
}

const std::string k_hdr_header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n";

TEST(PngData, EmptyDataChunksAreDroppedAndTheImageDecodesTheSame) {
    TempDir dir;
    Image image(5, 4);
    for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = Vec3(float(i) / 20.0f);
    write_image(dir / "a.png", image);
    const std::string png = testing::read_text(dir / "a.png");
    EXPECT_FALSE(png_without_empty_data_chunks(png));  // nothing to drop
    // An empty IDAT (length 0, type, any CRC: stb_image does not check it) after IHDR, the
    // chunk stb_image copied into a buffer it had not allocated.
    const std::string empty_idat = std::string(4, '\0') + "IDAT" + std::string(4, '\x55');
    const std::string with_empty = png.substr(0, 33) + empty_idat + png.substr(33);
    EXPECT_EQ(png_without_empty_data_chunks(with_empty), png);
    testing::write_text(dir / "b.png", with_empty);
    EXPECT_EQ(read_image(dir / "b.png").pixels, read_image(dir / "a.png").pixels);
}

TEST(HdrData, HeaderWithoutPixelsIsTruncated) {
    const std::string hdr = k_hdr_header + "-Y 20000 +X 20000\n";
    EXPECT_EQ(input_error_of([&] { check_hdr_data("a.hdr", hdr, 20000, 20000); }),
              "a.hdr: truncated file: the pixel data ends in scanline 1 of 20000");
}

TEST(HdrData, RunLengthScanlinesThatStopShortAreTruncated) {
    // 200 pixels wide: one run-length scanline of 2 runs per channel (200 = 128 + 72 ... as
    // 127 + 73), then the file ends in scanline 2.
    std::string line = std::string("\x02\x02", 2) + u16(200);
    for (int c = 0; c < 4; ++c) line += std::string("\xFF\x05\xC9\x05", 4);
    const std::string hdr = k_hdr_header + "-Y 3 +X 200\n" + line;
    EXPECT_EQ(input_error_of([&] { check_hdr_data("a.hdr", hdr, 200, 3); }),
              "a.hdr: truncated file: the pixel data ends in scanline 2 of 3");
    EXPECT_EQ(input_error_of([&] { check_hdr_data("a.hdr", hdr + line + line, 200, 3); }), "");
}

TEST(HdrData, FlatScanlinesNeedFourBytesAPixel) {
    const std::string hdr = k_hdr_header + "-Y 2 +X 4\n" + std::string(4 * 4 * 2 - 1, '\x40');
    EXPECT_NE(input_error_of([&] { check_hdr_data("a.hdr", hdr, 4, 2); }).find("truncated file"),
              std::string::npos);
    EXPECT_EQ(input_error_of([&] { check_hdr_data("a.hdr", hdr + "\x40", 4, 2); }), "");
}

TEST(HdrData, WrittenHdrPassesAndDecodes) {
    TempDir dir;
    Image image(64, 8, Vec3(2.0f, 0.5f, 0.125f));
    write_image(dir / "a.hdr", image);
    const Image back = read_image(dir / "a.hdr");
    EXPECT_NEAR(back.at(3, 3).x, 2.0f, 0.02f);
}

TEST(HdrData, TruncatedFileIsRefusedByReadImage) {
    TempDir dir;
    testing::write_text(dir / "a.hdr", k_hdr_header + "-Y 20000 +X 20000\n");
    EXPECT_NE(input_error_of([&] { read_image(dir / "a.hdr"); }).find("truncated file"),
              std::string::npos);
}

}  // namespace
}  // namespace hikari
