#include "hikari/io/images/deflate_runs.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <vector>

#include "hikari/core/rng.h"

namespace hikari {
namespace {

using Bytes = std::vector<uint8_t>;

/// zlib's inflate of a raw DEFLATE stream (no zlib header), the reference decoder.
Bytes inflate_raw(const Bytes& deflated, size_t expected_size) {
    Bytes out(expected_size + 1);
    z_stream z{};
    EXPECT_EQ(inflateInit2(&z, -15), Z_OK);
    z.next_in = const_cast<Bytef*>(deflated.data());
    z.avail_in = static_cast<uInt>(deflated.size());
    z.next_out = out.data();
    z.avail_out = static_cast<uInt>(out.size());
    EXPECT_EQ(inflate(&z, Z_FINISH), Z_STREAM_END);
    EXPECT_EQ(z.avail_in, 0u);  // nothing after the final block
    out.resize(z.total_out);
    inflateEnd(&z);
    return out;
}

/// Runs of every length around the 3..258 limits, random bytes, and a skewed distribution whose
/// Huffman code would exceed 15 bits without the length limit.
Bytes test_data() {
    Bytes data;
    for (int run = 1; run <= 600; run += (run < 270 ? 1 : 37))
        data.insert(data.end(), run, run & 0xFF);
    Pcg32 rng(7, 11);
    for (int i = 0; i < 5000; ++i) data.push_back(static_cast<uint8_t>(rng.next_u32()));
    for (int symbol = 0; symbol < 30; ++symbol)
        for (int k = 0; k < (1 << (symbol / 2)); ++k)
            data.push_back(static_cast<uint8_t>(symbol * 7));
    return data;
}

TEST(DeflateRuns, ZlibInflatesOneFinalPiece) {
    const Bytes data = test_data();
    Bytes deflated;
    deflate_runs(data, true, deflated);
    EXPECT_EQ(inflate_raw(deflated, data.size()), data);
    EXPECT_LT(deflated.size(), data.size());
}

TEST(DeflateRuns, PiecesConcatenateIntoOneStream) {
    const Bytes data = test_data();
    Bytes deflated;
    const size_t cuts[] = {0, 1, 700, 701, 30000, data.size()};
    for (size_t k = 0; k + 1 < std::size(cuts); ++k) {
        const std::span<const uint8_t> piece(data.data() + cuts[k], cuts[k + 1] - cuts[k]);
        deflate_runs(piece, k + 2 == std::size(cuts), deflated);
    }
    EXPECT_EQ(inflate_raw(deflated, data.size()), data);
}

TEST(DeflateRuns, RunsEndingAnywhereNearTheEnd) {
    // A run's end is found eight bytes at a time, then byte by byte within the last seven:
    // runs of every length that stop 0..9 bytes before the end of the data.
    for (int length = 1; length <= 20; ++length)
        for (int tail = 0; tail <= 9; ++tail) {
            Bytes data = {1, 2, 3};
            data.insert(data.end(), static_cast<size_t>(length), 9);
            for (int k = 0; k < tail; ++k) data.push_back(static_cast<uint8_t>(20 + k % 2));
            Bytes deflated;
            deflate_runs(data, true, deflated);
            ASSERT_EQ(inflate_raw(deflated, data.size()), data) << length << " " << tail;
        }
}

TEST(DeflateRuns, EmptyAndSingleByteInputs) {
    for (const Bytes& data : {Bytes{}, Bytes{42}, Bytes(1000, 0)}) {
        Bytes deflated;
        deflate_runs(data, true, deflated);
        EXPECT_EQ(inflate_raw(deflated, data.size()), data);
    }
}

}  // namespace
}  // namespace hikari
