#include "hikari/io/png_write.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <span>
#include <string_view>

#include "hikari/core/huge_page_allocator.h"
#include "hikari/core/parallel.h"
#include "hikari/core/simd_level.h"
#include "hikari/core/thread_scratch.h"
#include "hikari/io/deflate_runs.h"

namespace hikari {

namespace {

using Bytes = std::vector<uint8_t>;

/// Rows per band: each band is filtered and compressed on its own, so bands are the unit of
/// parallel work; fixed (not per thread) so the file does not depend on the thread count.
constexpr int k_band_rows = 32;

/// PNG filter types (ISO/IEC 15948 §9.2).
enum Filter : uint8_t { k_none = 0, k_sub = 1, k_up = 2, k_paeth = 4 };

void put_u32_be(uint8_t* p, uint32_t v) {
    p[0] = static_cast<uint8_t>(v >> 24);
    p[1] = static_cast<uint8_t>(v >> 16);
    p[2] = static_cast<uint8_t>(v >> 8);
    p[3] = static_cast<uint8_t>(v);
}

/// Appends a chunk: length, type, data, CRC-32 of type and data (§5.3).
void append_chunk(Bytes& out, std::string_view type, std::span<const uint8_t> data) {
    std::array<uint8_t, 8> head{};
    put_u32_be(head.data(), static_cast<uint32_t>(data.size()));
    std::memcpy(head.data() + 4, type.data(), 4);
    out.insert(out.end(), head.begin(), head.end());
    out.insert(out.end(), data.begin(), data.end());
    uLong crc = crc32(0L, head.data() + 4, 4);
    if (!data.empty()) crc = crc32(crc, data.data(), static_cast<uInt>(data.size()));
    std::array<uint8_t, 4> tail{};
    put_u32_be(tail.data(), static_cast<uint32_t>(crc));
    out.insert(out.end(), tail.begin(), tail.end());
}

/// Paeth's predictor (§9.4): whichever of left a, up b, upper-left c is nearest to
/// p = a + b − c (so |p − a| = |b − c|, |p − b| = |a − c|), ties to a, then b. Branch-free, so
/// the row loop below vectorises.
inline int paeth(int a, int b, int c) {
    const int pa = std::abs(b - c), pb = std::abs(a - c), pc = std::abs(a + b - 2 * c);
    const int b_or_c = pb <= pc ? b : c;
    return pa <= pb && pa <= pc ? a : b_or_c;
}

/// Filters one row of RGB bytes into `out` (filter byte first), choosing per row among Sub, Up
/// and Paeth the one with the smallest sum of |residual| as signed bytes: the heuristic the PNG
/// specification recommends (§12.8) and libpng uses. `prev` is the row above (zeros for row 0).
/// Inlined into one function per instruction set below.
[[gnu::always_inline]] inline void filter_row_body(const uint8_t* row, const uint8_t* prev,
                                                   size_t n, uint8_t* scratch, uint8_t* out) {
    uint8_t* __restrict sub = scratch;
    uint8_t* __restrict up = scratch + n;
    uint8_t* __restrict pae = scratch + 2 * n;
    uint32_t cost_sub = 0, cost_up = 0, cost_paeth = 0;
    auto cost = [](int r) { return static_cast<uint32_t>(std::abs(static_cast<int8_t>(r))); };
    // The first pixel has no left neighbour (a = c = 0); the rest is one branch-free loop.
    const size_t first = std::min<size_t>(3, n);
    for (size_t i = 0; i < first; ++i) {
        sub[i] = row[i];
        up[i] = static_cast<uint8_t>(row[i] - prev[i]);
        pae[i] = static_cast<uint8_t>(row[i] - paeth(0, prev[i], 0));
        cost_sub += cost(sub[i]), cost_up += cost(up[i]), cost_paeth += cost(pae[i]);
    }
    for (size_t i = first; i < n; ++i) {
        const int x = row[i], a = row[i - 3], b = prev[i], c = prev[i - 3];
        const auto s = static_cast<uint8_t>(x - a), u = static_cast<uint8_t>(x - b),
                   p = static_cast<uint8_t>(x - paeth(a, b, c));
        sub[i] = s, up[i] = u, pae[i] = p;
        cost_sub += cost(s), cost_up += cost(u), cost_paeth += cost(p);
    }
    const uint8_t* best = sub;
    out[0] = k_sub;
    if (cost_up < cost_sub) best = up, out[0] = k_up;
    if (cost_paeth < std::min(cost_sub, cost_up)) best = pae, out[0] = k_paeth;
    std::memcpy(out + 1, best, n);
}

// filter_row_body compiled for AVX-512 and AVX2 as well (the instruction sets of SimdLevel's
// checks): the loop then vectorises 16 or 8 pixels wide instead of 4, with the same bytes.
// Chosen at run time rather than by a target_clones ifunc, whose resolver runs before
// ThreadSanitizer's runtime is up.
void filter_row_portable(const uint8_t* row, const uint8_t* prev, size_t n, uint8_t* scratch,
                         uint8_t* out) {
    filter_row_body(row, prev, n, scratch, out);
}

[[gnu::target("avx2,avx512f,avx512vl,avx512dq,avx512bw")]] void filter_row_avx512(
    const uint8_t* row, const uint8_t* prev, size_t n, uint8_t* scratch, uint8_t* out) {
    filter_row_body(row, prev, n, scratch, out);
}

[[gnu::target("avx2")]] void filter_row_avx2(const uint8_t* row, const uint8_t* prev, size_t n,
                                             uint8_t* scratch, uint8_t* out) {
    filter_row_body(row, prev, n, scratch, out);
}

/// Adler-32 (RFC 1950 §8.2) of `data` continued from `adler`, 32 bytes at a time: over a block
/// of 32 bytes d_i, b grows by 32 a + Σ (32 − i) d_i and a by Σ d_i, sums the compiler
/// vectorises (zlib's adler32 adds one byte after another). Reduced modulo 65521 at least every
/// 5552 bytes, zlib's bound for 32-bit sums.
[[gnu::always_inline]] inline uint32_t adler32_body(uint32_t adler, const uint8_t* data, size_t n) {
    constexpr uint32_t k_modulus = 65521;
    constexpr size_t k_block = 32, k_blocks_between_reductions = 5552 / k_block;
    uint32_t a = adler & 0xFFFF, b = adler >> 16;
    while (n >= k_block) {
        size_t blocks = std::min(n / k_block, k_blocks_between_reductions);
        n -= blocks * k_block;
        for (; blocks > 0; --blocks, data += k_block) {
            uint32_t sum = 0, weighted = 0;
            for (size_t i = 0; i < k_block; ++i) {
                sum += data[i];
                weighted += static_cast<uint32_t>(k_block - i) * data[i];
            }
            b += static_cast<uint32_t>(k_block) * a + weighted;
            a += sum;
        }
        a %= k_modulus, b %= k_modulus;
    }
    for (; n > 0; --n) a += *data++, b += a;
    return (b % k_modulus) << 16 | (a % k_modulus);
}

uint32_t adler32_portable(uint32_t adler, const uint8_t* data, size_t n) {
    return adler32_body(adler, data, n);
}

[[gnu::target("avx2,avx512f,avx512vl,avx512dq,avx512bw")]] uint32_t adler32_avx512(
    uint32_t adler, const uint8_t* data, size_t n) {
    return adler32_body(adler, data, n);
}

[[gnu::target("avx2")]] uint32_t adler32_avx2(uint32_t adler, const uint8_t* data, size_t n) {
    return adler32_body(adler, data, n);
}

void filter_row(const uint8_t* row, const uint8_t* prev, size_t n, uint8_t* scratch, uint8_t* out) {
    simd_pick(best_simd_level(), filter_row_portable, filter_row_avx2, filter_row_avx512)(
        row, prev, n, scratch, out);
}

uint32_t adler32_update(uint32_t adler, const uint8_t* data, size_t n) {
    return simd_pick(best_simd_level(), adler32_portable, adler32_avx2, adler32_avx512)(adler, data,
                                                                                        n);
}

// thread_scratch buffers of encode_band.
struct FilteredRowsTag {};
struct FilterScratchTag {};

/// One band of rows [y0, y1), encoded: filtered, compressed.
struct Band {
    Bytes deflated;      ///< this band's DEFLATE piece
    uint32_t adler = 1;  ///< Adler-32 of the band's filtered bytes
    size_t filtered_size = 0;
};

Band encode_band(const Srgb8Image& image, int y0, int y1, bool last) {
    const size_t n = static_cast<size_t>(image.width) * 3;
    const std::vector<uint8_t> zeros(y0 == 0 ? n : 0, 0);  // the row above row 0
    Band band;
    band.filtered_size = (n + 1) * static_cast<size_t>(y1 - y0);
    // Every byte is written before it is read: no zero fill.
    uint8_t* const filtered = thread_scratch<uint8_t, FilteredRowsTag>(band.filtered_size);
    uint8_t* const scratch = thread_scratch<uint8_t, FilterScratchTag>(3 * n);
    for (int y = y0; y < y1; ++y) {
        // Up and Paeth predict from the row above, also across the band's top edge.
        const uint8_t* above = y > 0 ? image.row(y - 1) : zeros.data();
        filter_row(image.row(y), above, n, scratch,
                   filtered + (n + 1) * static_cast<size_t>(y - y0));
    }
    band.adler = adler32_update(1, filtered, band.filtered_size);
    deflate_runs({filtered, band.filtered_size}, last, band.deflated);
    return band;
}

}  // namespace

Bytes encode_png(const Srgb8Image& image) {
    const int band_count = (image.height + k_band_rows - 1) / k_band_rows;
    std::vector<Band> bands(static_cast<size_t>(band_count));
    hikari::parallel_for(0, band_count, [&](int b) {
        bands[static_cast<size_t>(b)] =
            encode_band(image, b * k_band_rows, std::min(image.height, (b + 1) * k_band_rows),
                        b == band_count - 1);
    });

    // The file's size is known now: one allocation, no copying as it grows.
    size_t size = 8 + 3 * 12 + 13 + 2 + 4 + 12;  // signature, IHDR, header, trailer, IEND
    for (const Band& band : bands) size += 12 + band.deflated.size();
    Bytes png;
    png.reserve(size);
    populate_pages(png.data(), size);
    png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    // IHDR (§11.2.2): size, bit depth 8, colour type 2 (RGB), deflate, adaptive filters, no
    // interlace.
    std::array<uint8_t, 13> header{};
    put_u32_be(header.data(), static_cast<uint32_t>(image.width));
    put_u32_be(header.data() + 4, static_cast<uint32_t>(image.height));
    header[8] = 8;
    header[9] = 2;
    append_chunk(png, "IHDR", header);
    // The zlib stream (RFC 1950) across IDAT chunks: header 78 01 (deflate, 32 KiB window,
    // fastest level; 0x7801 is a multiple of 31), one chunk per band, then the Adler-32 of all
    // the filtered bytes, combined from the bands' own.
    const std::array<uint8_t, 2> zlib_header = {0x78, 0x01};
    append_chunk(png, "IDAT", zlib_header);
    uLong adler = 1;
    for (const Band& band : bands) {
        append_chunk(png, "IDAT", band.deflated);
        adler = adler32_combine(adler, band.adler, static_cast<z_off_t>(band.filtered_size));
    }
    std::array<uint8_t, 4> trailer{};
    put_u32_be(trailer.data(), static_cast<uint32_t>(adler));
    append_chunk(png, "IDAT", trailer);
    append_chunk(png, "IEND", {});
    return png;
}

}  // namespace hikari
