#pragma once
// Linear float to 8-bit sRGB without a pow() per channel, with results identical to
// linear_to_srgb8(). The encoding is monotonic, so each code k is taken by one interval of floats
// [threshold[k], threshold[k + 1]); the thresholds are found once, by bisection on the float bit
// patterns against the reference conversion itself. A lookup then starts from the code at the
// start of a small bucket of floats (the top bits of the float) and steps over the at most one
// threshold inside that bucket.

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "hikari/core/image.h"
#include "hikari/core/simd_level.h"

namespace hikari {

class Srgb8Encoder {
  public:
    /// The shared encoder, built on first use (some 8000 reference conversions).
    static const Srgb8Encoder& instance();

    /// Same as linear_to_srgb8(v) for every float v, NaN and infinities included.
    uint8_t encode(float v) const {
        // No branch on the value (a picture's values mispredict): v outside (0, 1), NaN
        // included, is looked up as 0 (code 0), and v >= 1 is 255. One lookup: the bucket's
        // entry holds its first code and where in the bucket the next code begins, as the low
        // bits of that threshold (every float of a bucket shares the high bits).
        const bool inside = (v > 0.0f) & (v < 1.0f);
        const uint32_t bits = inside ? std::bit_cast<uint32_t>(v) : 0u;
        const uint32_t entry = m_bucket[bits >> k_bucket_shift];
        const uint32_t code = (entry & 0xFF) + ((bits & k_low_mask) >= (entry >> 8) ? 1 : 0);
        return v >= 1.0f ? uint8_t{255} : static_cast<uint8_t>(code);
    }

    /// Pixels [0, n) given one array per channel, encoded to interleaved RGB bytes rgb[0, 3n):
    /// the same bytes as encode() of each value, 8 or 16 values at a time with AVX2 or AVX-512
    /// gathers of the bucket table where the CPU has them.
    void encode_row(const float* red, const float* green, const float* blue, size_t n,
                    uint8_t* rgb) const;

    /// encode_row at a given SIMD level (which this CPU must support); every level gives the
    /// same bytes.
    void encode_row(const float* red, const float* green, const float* blue, size_t n, uint8_t* rgb,
                    SimdLevel level) const;

    /// The three codes of a linear RGB colour, written to out[0..2].
    void encode(Vec3 c, uint8_t* out) const {
        out[0] = encode(c.x), out[1] = encode(c.y), out[2] = encode(c.z);
    }

    /// The smallest float whose code is `code` (1 ≤ code ≤ 255); threshold(0) is 0.
    float threshold(int code) const { return m_threshold[code]; }

    // Buckets of floats sharing their top bits: 2^8 per octave (0.4% of the value), finer than
    // the spacing of the codes (at least 0.9% of the value), so a bucket holds at most one
    // threshold; the table is 128 KiB, of which renders touch the few KiB of values above 2^-13.
    // Public for the row kernels, which read the table the same way.
    static constexpr int k_bucket_shift = 15;
    static constexpr uint32_t k_low_mask = (1u << k_bucket_shift) - 1;

  private:
    Srgb8Encoder();

    static constexpr uint32_t k_one_bits = 0x3F800000;  // 1.0f
    static constexpr size_t k_buckets = (k_one_bits >> k_bucket_shift) + 1;

    std::array<float, 257> m_threshold{};  ///< [256] = infinity ends every search
    /// Per bucket: the code of its first float, plus 256 × the low bits of the next code's
    /// threshold when that lies in the bucket, else 256 × 2^k_bucket_shift (never reached).
    /// Written whole by the constructor, after populate_pages: no zero fill first, which would
    /// fault the 128 KiB in page by page (the table is built inside a render's first tile).
    std::array<uint32_t, k_buckets> m_bucket;
};

/// `image` encoded pixel by pixel (rows in parallel).
Srgb8Image encode_srgb8(const Image& image);

}  // namespace hikari
