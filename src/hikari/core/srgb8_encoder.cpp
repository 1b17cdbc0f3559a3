#include "hikari/core/srgb8_encoder.h"

#include <immintrin.h>

#include <array>
#include <limits>
#include <stdexcept>

#include "hikari/core/color.h"
#include "hikari/core/huge_page_allocator.h"
#include "hikari/core/parallel.h"

namespace hikari {

const Srgb8Encoder& Srgb8Encoder::instance() {
    static const Srgb8Encoder encoder;
    return encoder;
}

Srgb8Encoder::Srgb8Encoder() {
    populate_pages(m_bucket.data(), sizeof(m_bucket));
    // Positive floats order like their bit patterns, so bisect on the bits in (0, 1]: the
    // threshold of code k is the first float whose reference code reaches k.
    m_threshold[0] = 0.0f;
    uint32_t lo = 0;
    for (int code = 1; code <= 255; ++code) {
        uint32_t hi = k_one_bits;  // linear_to_srgb8(1) = 255 ≥ code
        while (lo < hi) {
            const uint32_t mid = lo + (hi - lo) / 2;
            if (linear_to_srgb8(std::bit_cast<float>(mid)) >= code)
                hi = mid;
            else
                lo = mid + 1;
        }
        m_threshold[code] = std::bit_cast<float>(lo);
    }
    m_threshold[256] = std::numeric_limits<float>::infinity();

    // Each bucket's first code, and where in it the next code starts. encode() steps at most
    // once: no bucket but the last (which holds only 1.0) holds more than one threshold.
    unsigned code = 0;
    for (size_t b = 0; b < k_buckets; ++b) {
        const float first = std::bit_cast<float>(static_cast<uint32_t>(b << k_bucket_shift));
        while (code < 255 && first >= m_threshold[code + 1]) ++code;
        const uint32_t next = std::bit_cast<uint32_t>(m_threshold[code + 1]);
        const bool next_inside = code < 255 && next >> k_bucket_shift == b;
        if (b + 1 < k_buckets && code + 2 <= 255 &&
            std::bit_cast<uint32_t>(m_threshold[code + 2]) >> k_bucket_shift == b)
            throw std::logic_error("Srgb8Encoder: a bucket holds more than one threshold");
        m_bucket[b] = code | (next_inside ? next & k_low_mask : k_low_mask + 1) << 8;
    }
}

namespace {

/// pshufb masks that interleave 16 red, 16 green and 16 blue bytes into 48 RGB bytes: mask
/// [out][channel] takes, for output register `out`, the bytes of that channel that land in it.
constexpr std::array<std::array<std::array<int8_t, 16>, 3>, 3> make_interleave_masks() {
    std::array<std::array<std::array<int8_t, 16>, 3>, 3> masks{};
    for (int out = 0; out < 3; ++out)
        for (int channel = 0; channel < 3; ++channel)
            for (int k = 0; k < 16; ++k) {
                const int m = 16 * out + k;  // byte m of the 48 is pixel m / 3, channel m % 3
                masks[out][channel][k] = static_cast<int8_t>(m % 3 == channel ? m / 3 : -1);
            }
    return masks;
}
constexpr auto k_interleave = make_interleave_masks();

[[gnu::target("ssse3")]] void interleave_rgb(__m128i r, __m128i g, __m128i b, uint8_t* rgb) {
    for (int out = 0; out < 3; ++out) {
        const auto mask = [&](int channel) {
            return _mm_loadu_si128(
                reinterpret_cast<const __m128i*>(k_interleave[out][channel].data()));
        };
        const __m128i bytes =
            _mm_or_si128(_mm_or_si128(_mm_shuffle_epi8(r, mask(0)), _mm_shuffle_epi8(g, mask(1))),
                         _mm_shuffle_epi8(b, mask(2)));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(rgb + 16 * out), bytes);
    }
}

// GCC 12's AVX-512 intrinsics start from _mm512_undefined_epi32(), which -Wmaybe-uninitialized
// reports at every use (GCC bug 105593, fixed in GCC 13).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

/// encode() of 16 values: the same steps in AVX-512 lanes, the table read by one gather.
[[gnu::target("avx512f,avx512bw,avx512vl,ssse3")]] __m128i encode16(const uint32_t* table,
                                                                    const float* v) {
    const __m512 x = _mm512_loadu_ps(v);
    const __mmask16 inside = _mm512_cmp_ps_mask(x, _mm512_setzero_ps(), _CMP_GT_OQ) &
                             _mm512_cmp_ps_mask(x, _mm512_set1_ps(1.0f), _CMP_LT_OQ);
    const __mmask16 saturated = _mm512_cmp_ps_mask(x, _mm512_set1_ps(1.0f), _CMP_GE_OQ);
    const __m512i bits = _mm512_maskz_mov_epi32(inside, _mm512_castps_si512(x));
    const __m512i entry =
        _mm512_i32gather_epi32(_mm512_srli_epi32(bits, Srgb8Encoder::k_bucket_shift), table, 4);
    const __mmask16 step =
        _mm512_cmpge_epu32_mask(_mm512_and_si512(bits, _mm512_set1_epi32(Srgb8Encoder::k_low_mask)),
                                _mm512_srli_epi32(entry, 8));
    __m512i code = _mm512_and_si512(entry, _mm512_set1_epi32(0xFF));
    code = _mm512_mask_add_epi32(code, step, code, _mm512_set1_epi32(1));
    code = _mm512_mask_mov_epi32(code, saturated, _mm512_set1_epi32(255));
    return _mm512_cvtepi32_epi8(code);
}

[[gnu::target("avx512f,avx512bw,avx512vl,ssse3")]] size_t encode_row_avx512(
    const uint32_t* table, const float* red, const float* green, const float* blue, size_t n,
    uint8_t* rgb) {
    size_t i = 0;
    for (; i + 16 <= n; i += 16)
        interleave_rgb(encode16(table, red + i), encode16(table, green + i),
                       encode16(table, blue + i), rgb + 3 * i);
    return i;
}

#pragma GCC diagnostic pop

/// encode() of 8 values in AVX2 lanes, as 8 bytes in the low half.
[[gnu::target("avx2,ssse3")]] __m128i encode8(const uint32_t* table, const float* v) {
    const __m256 x = _mm256_loadu_ps(v);
    const __m256 one = _mm256_set1_ps(1.0f);
    const __m256 inside = _mm256_and_ps(_mm256_cmp_ps(x, _mm256_setzero_ps(), _CMP_GT_OQ),
                                        _mm256_cmp_ps(x, one, _CMP_LT_OQ));
    const __m256i saturated = _mm256_castps_si256(_mm256_cmp_ps(x, one, _CMP_GE_OQ));
    const __m256i bits = _mm256_and_si256(_mm256_castps_si256(x), _mm256_castps_si256(inside));
    const __m256i entry =
        _mm256_i32gather_epi32(reinterpret_cast<const int*>(table),
                               _mm256_srli_epi32(bits, Srgb8Encoder::k_bucket_shift), 4);
    // Unsigned low >= threshold as signed (both below 2^16): not (threshold > low).
    const __m256i low = _mm256_and_si256(bits, _mm256_set1_epi32(Srgb8Encoder::k_low_mask));
    const __m256i below = _mm256_cmpgt_epi32(_mm256_srli_epi32(entry, 8), low);
    __m256i code = _mm256_and_si256(entry, _mm256_set1_epi32(0xFF));
    code = _mm256_sub_epi32(code, _mm256_andnot_si256(below, _mm256_set1_epi32(-1)));
    code = _mm256_blendv_epi8(code, _mm256_set1_epi32(255), saturated);
    // 8 codes of 32 bits to bytes: pack to 16 bits, then to 8.
    const __m128i words =
        _mm_packus_epi32(_mm256_castsi256_si128(code), _mm256_extracti128_si256(code, 1));
    return _mm_packus_epi16(words, words);
}

[[gnu::target("avx2,ssse3")]] size_t encode_row_avx2(const uint32_t* table, const float* red,
                                                     const float* green, const float* blue,
                                                     size_t n, uint8_t* rgb) {
    size_t i = 0;
    for (; i + 16 <= n; i += 16) {
        const auto halves = [&](const float* v) {
            return _mm_unpacklo_epi64(encode8(table, v + i), encode8(table, v + i + 8));
        };
        interleave_rgb(halves(red), halves(green), halves(blue), rgb + 3 * i);
    }
    return i;
}

/// No row kernel: every value goes to encode_row's scalar loop.
size_t encode_row_portable(const uint32_t*, const float*, const float*, const float*, size_t,
                           uint8_t*) {
    return 0;
}

}  // namespace

void Srgb8Encoder::encode_row(const float* red, const float* green, const float* blue, size_t n,
                              uint8_t* rgb) const {
    encode_row(red, green, blue, n, rgb, best_simd_level());
}

void Srgb8Encoder::encode_row(const float* red, const float* green, const float* blue, size_t n,
                              uint8_t* rgb, SimdLevel level) const {
    // The kernel encodes whole steps of 16 values; the rest one at a time.
    const size_t done = simd_pick(level, encode_row_portable, encode_row_avx2, encode_row_avx512)(
        m_bucket.data(), red, green, blue, n, rgb);
    for (size_t i = done; i < n; ++i) {
        rgb[3 * i] = encode(red[i]);
        rgb[3 * i + 1] = encode(green[i]);
        rgb[3 * i + 2] = encode(blue[i]);
    }
}

Srgb8Image encode_srgb8(const Image& image) {
    const Srgb8Encoder& srgb = Srgb8Encoder::instance();
    Srgb8Image out(image.width, image.height);
    hikari::parallel_for(0, image.height, [&](int y) {
        uint8_t* row = out.row(y);
        for (int x = 0; x < image.width; ++x) srgb.encode(image.at(x, y), row + 3 * x);
    });
    return out;
}

}  // namespace hikari
