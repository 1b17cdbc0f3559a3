// PNG decompression bombs and oversized headers under --max-memory (issue 41, class 6): refused
// from the header or stopped by the allocation cap, with the peak memory measured.

#include "hikari/io/images/stb_image_bounded.h"

#include <zlib.h>

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../../support/input_error.h"
#include "../../support/peak_memory.h"
#include "../temp_dir.h"
#include "hikari/core/memory_budget.h"
#include "hikari/io/images/image_read.h"

namespace hikari {
namespace {

using testing::input_error_of;
using testing::TempDir;

std::string u32(uint32_t v) {
    return {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8),
            static_cast<char>(v)};
}

std::string png_chunk(const std::string& type, const std::string& data) {
    const std::string body = type + data;
    const auto crc = static_cast<uint32_t>(
        crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size())));
    return u32(static_cast<uint32_t>(data.size())) + body + u32(crc);
}

/// `zero_bytes` zeros deflated in small steps (zlib, RFC 1950), so the test never holds them.
std::string deflated_zeros(size_t zero_bytes) {
    z_stream z{};
    deflateInit(&z, 9);
    std::vector<unsigned char> zeros(1 << 20, 0), out(1 << 16);
    std::string result;
    for (size_t left = zero_bytes;;) {
        const size_t step = std::min(left, zeros.size());
        left -= step;
        z.next_in = zeros.data();
        z.avail_in = static_cast<uInt>(step);
        const int flush = left == 0 ? Z_FINISH : Z_NO_FLUSH;
        int status = Z_OK;
        do {
            z.next_out = out.data();
            z.avail_out = static_cast<uInt>(out.size());
            status = deflate(&z, flush);
            result.append(reinterpret_cast<const char*>(out.data()), out.size() - z.avail_out);
        } while (z.avail_out == 0);
        if (status == Z_STREAM_END) break;
    }
    deflateEnd(&z);
    return result;
}

/// A PNG of `w` × `h` at `bit_depth` (colour type 0 grey, or 2 RGB) whose image data inflates to
/// `inflated` zero bytes, whatever its size needs.
std::string png(uint32_t w, uint32_t h, int bit_depth, int colour_type, size_t inflated) {
    const std::string ihdr = u32(w) + u32(h) + static_cast<char>(bit_depth) +
                             static_cast<char>(colour_type) + std::string(3, '\0');
    return std::string("\x89PNG\r\n\x1a\n", 8) + png_chunk("IHDR", ihdr) +
           png_chunk("IDAT", deflated_zeros(inflated)) + png_chunk("IEND", "");
}

class PngBomb : public ::testing::Test {
  protected:
    void TearDown() override { set_memory_limit(m_memory); }
    TempDir m_dir;

  private:
    double m_memory = memory_limit();
};

TEST_F(PngBomb, DataInflatingPastTheSizeIsRefusedWithinTheCap) {
    // 8×8 RGB needs 8 × 25 bytes inflated; the data inflates to 256 MiB.
    testing::write_text(m_dir / "bomb.png", png(8, 8, 8, 2, size_t{256} << 20));
    set_memory_limit(0.25 * (1 << 30));
    const auto run = testing::run_in_child([&] { read_image(m_dir / "bomb.png"); });
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_LT(run.extra_peak_bytes, 32.0 * (1 << 20));
    EXPECT_EQ(input_error_of([&] { read_image(m_dir / "bomb.png"); }),
              (m_dir / "bomb.png").string() +
                  ": cannot decode image: its data needs more than the 1.03 MiB its 8x8 size "
                  "allows (a decompression bomb?)");
}

TEST_F(PngBomb, OneBitImageIsRefusedFromItsHeaderByDecodedSize) {
    // 16384² at 1 bit a pixel: 32 MiB of rows inflate from a few KiB, 7 GiB decoded.
    const uint32_t side = 16384;
    testing::write_text(m_dir / "big.png", png(side, side, 1, 0, size_t{side / 8 + 1} * side));
    set_memory_limit(0.25 * (1 << 30));
    const auto run = testing::run_in_child([&] { read_image(m_dir / "big.png"); });
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_LT(run.extra_peak_bytes, 32.0 * (1 << 20));
    EXPECT_EQ(input_error_of([&] { read_image(m_dir / "big.png"); }),
              (m_dir / "big.png").string() +
                  ": decoding a 16384x16384 image needs about 7 GiB, more than the limit of "
                  "0.25 GiB (raise it with --max-memory 7 or more)");
}

TEST_F(PngBomb, HonestImageDecodesUnderTheCap) {
    // 64 × 32 RGB: exactly its rows of zeros (a filter byte and 192 samples each).
    testing::write_text(m_dir / "ok.png", png(64, 32, 8, 2, 32 * (1 + 64 * 3)));
    const Image image = read_image(m_dir / "ok.png");
    EXPECT_EQ(image.width, 64);
    EXPECT_EQ(image.height, 32);
    EXPECT_EQ(image.at(5, 5), Vec3(0.0f));
}

TEST(StbAllocationCap, RefusesLargerAllocationsOnlyWhileAlive) {
    const std::string bytes = png(64, 32, 8, 2, 32 * (1 + 64 * 3));
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    int w = 0, h = 0, n = 0;
    {
        const stb::AllocationCap cap(100);
        EXPECT_EQ(stb::load_8(data, static_cast<int>(bytes.size()), &w, &h, &n, 3), nullptr);
        EXPECT_TRUE(cap.exceeded());
    }
    unsigned char* pixels = stb::load_8(data, static_cast<int>(bytes.size()), &w, &h, &n, 3);
    EXPECT_NE(pixels, nullptr);
    stb::image_free(pixels);
}

}  // namespace
}  // namespace hikari
