#include "hikari/io/images/png_write.h"

#include <zlib.h>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <span>
#include <string_view>

#include "hikari/core/cancel.h"
#include "hikari/core/color.h"
#include "hikari/core/huge_page_allocator.h"
#include "hikari/core/parallel.h"
#include "hikari/core/simd_level.h"
#include "hikari/core/thread_scratch.h"
#include "hikari/io/images/deflate_runs.h"

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

#if defined(__x86_64__)
/// The sum of a register's 64-bit lanes.
[[gnu::target("avx2")]] inline uint64_t sum_lanes_64(__m128i v) {
    return static_cast<uint64_t>(_mm_cvtsi128_si64(v)) +
           static_cast<uint64_t>(_mm_extract_epi64(v, 1));
}

[[gnu::target("avx2")]] inline uint64_t sum_lanes_64(__m256i v) {
    return sum_lanes_64(_mm_add_epi64(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1)));
}
#endif

/// A row's three candidate filterings (Sub, Up, Paeth) and their costs, the sums of
/// |residual| as signed bytes.
struct RowFilters {
    uint8_t* __restrict sub;
    uint8_t* __restrict up;
    uint8_t* __restrict paeth;
    uint32_t cost_sub = 0, cost_up = 0, cost_paeth = 0;
};

inline uint32_t filter_cost(uint8_t residual) {
    return static_cast<uint32_t>(std::abs(static_cast<int8_t>(residual)));
}

/// Bytes [begin, end) of the three filterings, begin ≥ Bpp (a pixel to the left exists). Bpp:
/// bytes per pixel, 3 for 8-bit RGB, 6 for 16-bit (filters pair bytes a pixel apart, §9.2).
template <size_t Bpp = 3>
[[gnu::always_inline]] inline void filter_bytes(const uint8_t* row, const uint8_t* prev,
                                                size_t begin, size_t end, RowFilters& f) {
    uint32_t cost_sub = 0, cost_up = 0, cost_paeth = 0;
    for (size_t i = begin; i < end; ++i) {
        const int x = row[i], a = row[i - Bpp], b = prev[i], c = prev[i - Bpp];
        const auto s = static_cast<uint8_t>(x - a), u = static_cast<uint8_t>(x - b),
                   p = static_cast<uint8_t>(x - paeth(a, b, c));
        f.sub[i] = s, f.up[i] = u, f.paeth[i] = p;
        cost_sub += filter_cost(s), cost_up += filter_cost(u), cost_paeth += filter_cost(p);
    }
    f.cost_sub += cost_sub, f.cost_up += cost_up, f.cost_paeth += cost_paeth;
}

/// The first pixel's bytes, which have no left neighbour (a = c = 0).
template <size_t Bpp = 3>
inline RowFilters filter_first_pixel(const uint8_t* row, const uint8_t* prev, size_t n,
                                     uint8_t* scratch) {
    RowFilters f{scratch, scratch + n, scratch + 2 * n};
    for (size_t i = 0; i < std::min<size_t>(Bpp, n); ++i) {
        f.sub[i] = row[i];
        f.up[i] = static_cast<uint8_t>(row[i] - prev[i]);
        f.paeth[i] = static_cast<uint8_t>(row[i] - paeth(0, prev[i], 0));
        f.cost_sub += filter_cost(f.sub[i]), f.cost_up += filter_cost(f.up[i]);
        f.cost_paeth += filter_cost(f.paeth[i]);
    }
    return f;
}

/// Writes the cheapest filtering to `out`, filter byte first (ties: Sub, then Up).
inline void write_cheapest(const RowFilters& f, size_t n, uint8_t* out) {
    const uint8_t* best = f.sub;
    out[0] = k_sub;
    if (f.cost_up < f.cost_sub) best = f.up, out[0] = k_up;
    if (f.cost_paeth < std::min(f.cost_sub, f.cost_up)) best = f.paeth, out[0] = k_paeth;
    std::memcpy(out + 1, best, n);
}

// filter_row: filters one row of RGB bytes into `out` (filter byte first), choosing per row
// among Sub, Up and Paeth the one with the smallest sum of |residual| as signed bytes, the
// heuristic the PNG specification recommends (§12.8) and libpng uses. `prev` is the row above
// (zeros for row 0); `scratch` holds 3 n bytes. One build per instruction set, chosen at run
// time rather than by a target_clones ifunc, whose resolver runs before ThreadSanitizer's
// runtime is up; all write the same bytes.
void filter_row_portable(const uint8_t* row, const uint8_t* prev, size_t n, uint8_t* scratch,
                         uint8_t* out) {
    RowFilters f = filter_first_pixel(row, prev, n, scratch);
    filter_bytes(row, prev, std::min<size_t>(3, n), n, f);
    write_cheapest(f, n, out);
}

/// filter_row_portable for 16-bit RGB rows (6 bytes per pixel). 16-bit output is rare and
/// slow anyway (a pow() per sample), so it has no SIMD kernels.
void filter_row_16bit(const uint8_t* row, const uint8_t* prev, size_t n, uint8_t* scratch,
                      uint8_t* out) {
    RowFilters f = filter_first_pixel<6>(row, prev, n, scratch);
    filter_bytes<6>(row, prev, std::min<size_t>(6, n), n, f);
    write_cheapest(f, n, out);
}

#if defined(__x86_64__)
/// 16 bytes per step: Paeth's predictor chosen in 16-bit lanes (its distances reach ±510), the
/// residuals as byte differences, and each cost as vpsadbw over |residual| (vpabsb reads a
/// byte as signed, as filter_cost does). The few bytes past the last whole step go through
/// filter_bytes.
[[gnu::target("avx2")]] void filter_row_avx2(const uint8_t* row, const uint8_t* prev, size_t n,
                                             uint8_t* scratch, uint8_t* out) {
    RowFilters f = filter_first_pixel(row, prev, n, scratch);
    constexpr size_t k_step = 16;
    const auto load = [](const uint8_t* p) {
        return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
    };
    __m128i cost_sub = _mm_setzero_si128(), cost_up = cost_sub, cost_paeth = cost_sub;
    size_t i = 3;
    for (; n >= k_step && i <= n - k_step; i += k_step) {
        const __m128i x = load(row + i), a = load(row + i - 3), b = load(prev + i),
                      c = load(prev + i - 3);
        const __m256i a16 = _mm256_cvtepu8_epi16(a), b16 = _mm256_cvtepu8_epi16(b),
                      c16 = _mm256_cvtepu8_epi16(c);
        const __m256i pa = _mm256_abs_epi16(_mm256_sub_epi16(b16, c16));
        const __m256i pb = _mm256_abs_epi16(_mm256_sub_epi16(a16, c16));
        const __m256i pc = _mm256_abs_epi16(
            _mm256_sub_epi16(_mm256_add_epi16(a16, b16), _mm256_add_epi16(c16, c16)));
        // paeth(): a where pa ≤ pb and pa ≤ pc, else b where pb ≤ pc, else c.
        const __m256i b_or_c = _mm256_blendv_epi8(b16, c16, _mm256_cmpgt_epi16(pb, pc));
        const __m256i not_a =
            _mm256_or_si256(_mm256_cmpgt_epi16(pa, pb), _mm256_cmpgt_epi16(pa, pc));
        const __m256i predicted16 = _mm256_blendv_epi8(a16, b_or_c, not_a);
        const __m256i packed = _mm256_packus_epi16(predicted16, predicted16);
        const __m128i predicted = _mm256_castsi256_si128(_mm256_permute4x64_epi64(packed, 0x08));
        const __m128i s = _mm_sub_epi8(x, a), u = _mm_sub_epi8(x, b),
                      p = _mm_sub_epi8(x, predicted);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(f.sub + i), s);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(f.up + i), u);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(f.paeth + i), p);
        const __m128i zero = _mm_setzero_si128();
        cost_sub = _mm_add_epi64(cost_sub, _mm_sad_epu8(_mm_abs_epi8(s), zero));
        cost_up = _mm_add_epi64(cost_up, _mm_sad_epu8(_mm_abs_epi8(u), zero));
        cost_paeth = _mm_add_epi64(cost_paeth, _mm_sad_epu8(_mm_abs_epi8(p), zero));
    }
    f.cost_sub += static_cast<uint32_t>(sum_lanes_64(cost_sub));
    f.cost_up += static_cast<uint32_t>(sum_lanes_64(cost_up));
    f.cost_paeth += static_cast<uint32_t>(sum_lanes_64(cost_paeth));
    filter_bytes(row, prev, std::min(i, n), n, f);
    write_cheapest(f, n, out);
}

/// AVX-512 CPUs run the AVX2 code: it measured faster than the compiler's AVX-512
/// vectorisation of filter_bytes, which widens every byte to 32 bits.
void filter_row_avx512(const uint8_t* row, const uint8_t* prev, size_t n, uint8_t* scratch,
                       uint8_t* out) {
    filter_row_avx2(row, prev, n, scratch, out);
}
#else
void filter_row_avx2(const uint8_t* row, const uint8_t* prev, size_t n, uint8_t* scratch,
                     uint8_t* out) {
    filter_row_portable(row, prev, n, scratch, out);
}

void filter_row_avx512(const uint8_t* row, const uint8_t* prev, size_t n, uint8_t* scratch,
                       uint8_t* out) {
    filter_row_portable(row, prev, n, scratch, out);
}
#endif

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

#if defined(__x86_64__)
/// Adler-32 as adler32_body, 32 bytes per step in AVX2 registers (the method of zlib-ng's and
/// Chromium's SIMD Adler-32): vpsadbw sums a block's bytes, vpmaddubsw and vpmaddwd its bytes
/// weighted 32..1, and a third register collects the running sum a at the start of every block,
/// which b needs 32 times. Lanes hold partial sums until the reduction, at least every 5552
/// bytes as in adler32_body (in 64-bit arithmetic here, as 32 times the collected sums can
/// exceed 32 bits).
[[gnu::target("avx2")]] uint32_t adler32_avx2(uint32_t adler, const uint8_t* data, size_t n) {
    constexpr uint32_t k_modulus = 65521;
    constexpr size_t k_block = 32, k_blocks_between_reductions = 5552 / k_block;
    const __m256i weights =
        _mm256_setr_epi8(32, 31, 30, 29, 28, 27, 26, 25, 24, 23, 22, 21, 20, 19, 18, 17, 16, 15, 14,
                         13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1);
    const __m256i ones = _mm256_set1_epi16(1), zero = _mm256_setzero_si256();
    uint64_t a = adler & 0xFFFF, b = adler >> 16;
    while (n >= k_block) {
        const size_t blocks = std::min(n / k_block, k_blocks_between_reductions);
        n -= blocks * k_block;
        __m256i sums = zero;      // Σ bytes, four 64-bit lanes
        __m256i earlier = zero;   // Σ over blocks of `sums` before the block
        __m256i weighted = zero;  // Σ (32 − i) byte_i, eight 32-bit lanes
        for (size_t k = 0; k < blocks; ++k, data += k_block) {
            const __m256i bytes = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(data));
            earlier = _mm256_add_epi64(earlier, sums);
            sums = _mm256_add_epi64(sums, _mm256_sad_epu8(bytes, zero));
            weighted = _mm256_add_epi32(
                weighted, _mm256_madd_epi16(_mm256_maddubs_epi16(bytes, weights), ones));
        }
        const __m256i weighted_64 =
            _mm256_add_epi64(_mm256_cvtepu32_epi64(_mm256_castsi256_si128(weighted)),
                             _mm256_cvtepu32_epi64(_mm256_extracti128_si256(weighted, 1)));
        b += k_block * (blocks * a + sum_lanes_64(earlier)) + sum_lanes_64(weighted_64);
        a += sum_lanes_64(sums);
        a %= k_modulus, b %= k_modulus;
    }
    return adler32_body(static_cast<uint32_t>(b << 16 | a), data, n);
}

/// AVX-512 CPUs run the AVX2 code, after which Adler-32 is a small part of the encode.
uint32_t adler32_avx512(uint32_t adler, const uint8_t* data, size_t n) {
    return adler32_avx2(adler, data, n);
}
#else
uint32_t adler32_avx2(uint32_t adler, const uint8_t* data, size_t n) {
    return adler32_body(adler, data, n);
}

uint32_t adler32_avx512(uint32_t adler, const uint8_t* data, size_t n) {
    return adler32_body(adler, data, n);
}
#endif

void filter_row(SimdLevel level, const uint8_t* row, const uint8_t* prev, size_t n,
                uint8_t* scratch, uint8_t* out) {
    simd_pick(level, filter_row_portable, filter_row_avx2, filter_row_avx512)(row, prev, n, scratch,
                                                                              out);
}

uint32_t adler32_update(SimdLevel level, uint32_t adler, const uint8_t* data, size_t n) {
    return simd_pick(level, adler32_portable, adler32_avx2, adler32_avx512)(adler, data, n);
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

/// The samples of an image as the PNG encoder reads them: rows of RGB samples, 8 or 16 bits.
struct RawRows {
    const uint8_t* data;
    int width, height;
    int bit_depth;  ///< 8 or 16 (samples big-endian)

    size_t pixel_bytes() const { return bit_depth == 16 ? 6 : 3; }
    size_t row_bytes() const { return static_cast<size_t>(width) * pixel_bytes(); }
    const uint8_t* row(int y) const { return data + static_cast<size_t>(y) * row_bytes(); }
};

Band encode_band(const RawRows& image, int y0, int y1, bool last, SimdLevel level) {
    throw_if_cancelled();  // SIGINT / SIGTERM: once per band of rows
    const size_t n = image.row_bytes();
    const std::vector<uint8_t> zeros(y0 == 0 ? n : 0, 0);  // the row above row 0
    Band band;
    band.filtered_size = (n + 1) * static_cast<size_t>(y1 - y0);
    // Every byte is written before it is read: no zero fill.
    uint8_t* const filtered = thread_scratch<uint8_t, FilteredRowsTag>(band.filtered_size);
    uint8_t* const scratch = thread_scratch<uint8_t, FilterScratchTag>(3 * n);
    for (int y = y0; y < y1; ++y) {
        // Up and Paeth predict from the row above, also across the band's top edge.
        const uint8_t* above = y > 0 ? image.row(y - 1) : zeros.data();
        uint8_t* const out = filtered + (n + 1) * static_cast<size_t>(y - y0);
        if (image.bit_depth == 16)
            filter_row_16bit(image.row(y), above, n, scratch, out);
        else
            filter_row(level, image.row(y), above, n, scratch, out);
    }
    band.adler = adler32_update(level, 1, filtered, band.filtered_size);
    deflate_runs({filtered, band.filtered_size}, last, band.deflated);
    return band;
}

/// The PNG file of `image`'s samples.
Bytes encode_png(const RawRows& image, SimdLevel level) {
    const int band_count = (image.height + k_band_rows - 1) / k_band_rows;
    std::vector<Band> bands(static_cast<size_t>(band_count));
    hikari::parallel_for(0, band_count, [&](int b) {
        bands[static_cast<size_t>(b)] =
            encode_band(image, b * k_band_rows, std::min(image.height, (b + 1) * k_band_rows),
                        b == band_count - 1, level);
    });

    // The file's size is known now: one allocation, no copying as it grows.
    size_t size = 8 + 3 * 12 + 13 + 2 + 4 + 12;  // signature, IHDR, header, trailer, IEND
    for (const Band& band : bands) size += 12 + band.deflated.size();
    Bytes png;
    png.reserve(size);
    populate_pages(png.data(), size);
    png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    // IHDR (§11.2.2): size, bit depth 8 or 16, colour type 2 (RGB), deflate, adaptive filters,
    // no interlace.
    std::array<uint8_t, 13> header{};
    put_u32_be(header.data(), static_cast<uint32_t>(image.width));
    put_u32_be(header.data() + 4, static_cast<uint32_t>(image.height));
    header[8] = static_cast<uint8_t>(image.bit_depth);
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

}  // namespace

Bytes encode_png(const Srgb8Image& image, SimdLevel level) {
    return encode_png(RawRows{image.bytes.data(), image.width, image.height, 8}, level);
}

Bytes encode_png(const Srgb16Image& image, SimdLevel level) {
    return encode_png(RawRows{image.bytes.data(), image.width, image.height, 16}, level);
}

Srgb16Image encode_srgb16(const Image& image) {
    Srgb16Image out{image.width, image.height, {}};
    out.bytes.resize(image.pixels.size() * 6);
    hikari::parallel_for(0, image.height, [&](int y) {
        const size_t first = static_cast<size_t>(y) * static_cast<size_t>(image.width);
        for (size_t i = first; i < first + static_cast<size_t>(image.width); ++i)
            for (int c = 0; c < 3; ++c) {
                // Rounded from the curve itself, not widened from the 8-bit code.
                const auto code = static_cast<uint16_t>(
                    std::lround(linear_to_srgb(image.pixels[i][c]) * 65535.0f));
                out.bytes[6 * i + 2 * c] = static_cast<uint8_t>(code >> 8);
                out.bytes[6 * i + 2 * c + 1] = static_cast<uint8_t>(code);
            }
    });
    return out;
}

}  // namespace hikari
