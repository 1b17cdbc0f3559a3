#include "hikari/core/srgb8_encoder.h"

#include <limits>
#include <stdexcept>

#include "hikari/core/color.h"
#include "hikari/core/parallel.h"

namespace hikari {

const Srgb8Encoder& Srgb8Encoder::instance() {
    static const Srgb8Encoder encoder;
    return encoder;
}

Srgb8Encoder::Srgb8Encoder() {
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

    // The code of each bucket's first float.
    unsigned code = 0;
    for (size_t b = 0; b < k_buckets; ++b) {
        const float first = std::bit_cast<float>(static_cast<uint32_t>(b << k_bucket_shift));
        while (code < 255 && first >= m_threshold[code + 1]) ++code;
        m_bucket_start[b] = static_cast<uint8_t>(code);
    }
    // encode() steps at most once: every bucket but the last (which holds only 1.0) starts at
    // most one code below the next one's start.
    for (size_t b = 0; b + 1 < k_buckets; ++b)
        if (m_bucket_start[b + 1] - m_bucket_start[b] > 1)
            throw std::logic_error("Srgb8Encoder: a bucket holds more than one threshold");
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
