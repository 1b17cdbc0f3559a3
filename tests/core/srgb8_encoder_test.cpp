#include "hikari/core/srgb8_encoder.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <vector>

#include "hikari/core/color.h"
#include "hikari/core/rng.h"

namespace hikari {
namespace {

TEST(Srgb8Encoder, ThresholdsAreWhereTheReferenceCodeChanges) {
    const Srgb8Encoder& srgb = Srgb8Encoder::instance();
    for (int code = 1; code <= 255; ++code) {
        const float t = srgb.threshold(code);
        EXPECT_EQ(linear_to_srgb8(t), code) << "code " << code;
        EXPECT_EQ(linear_to_srgb8(std::nextafter(t, 0.0f)), code - 1) << "code " << code;
        EXPECT_EQ(srgb.encode(t), code);
        EXPECT_EQ(srgb.encode(std::nextafter(t, 0.0f)), code - 1);
    }
}

TEST(Srgb8Encoder, EqualsTheReferenceOnASweepOfAllFloatsInZeroOne) {
    // Every 61st bit pattern from 0 to 1 (17 million floats), plus the neighbourhoods above.
    const Srgb8Encoder& srgb = Srgb8Encoder::instance();
    for (uint32_t bits = 0; bits <= 0x3F800000u; bits += 61) {
        const float v = std::bit_cast<float>(bits);
        ASSERT_EQ(srgb.encode(v), linear_to_srgb8(v)) << "v = " << v;
    }
}

TEST(Srgb8Encoder, ClampsLikeTheReference) {
    const Srgb8Encoder& srgb = Srgb8Encoder::instance();
    constexpr float inf = std::numeric_limits<float>::infinity();
    for (float v :
         {-inf, -1.0f, -0.0f, 0.0f, 1.0f, 1.5f, 1e30f, inf, std::numeric_limits<float>::quiet_NaN(),
          std::numeric_limits<float>::denorm_min()})
        EXPECT_EQ(srgb.encode(v), linear_to_srgb8(v)) << "v = " << v;
}

TEST(Srgb8Encoder, RowsEqualEncodeOfEachValueAtEverySimdLevel) {
    const Srgb8Encoder& encoder = Srgb8Encoder::instance();
    // Values at and beside every threshold, random ones, and the special cases; lengths that
    // are not multiples of the SIMD widths.
    std::vector<float> values = {0.0f,
                                 -0.0f,
                                 -1.0f,
                                 1.0f,
                                 2.0f,
                                 std::numeric_limits<float>::infinity(),
                                 -std::numeric_limits<float>::infinity(),
                                 std::numeric_limits<float>::quiet_NaN(),
                                 std::numeric_limits<float>::denorm_min()};
    for (int code = 1; code <= 255; ++code) {
        const float t = encoder.threshold(code);
        values.push_back(t);
        values.push_back(std::nextafter(t, 0.0f));
        values.push_back(std::nextafter(t, 2.0f));
    }
    Pcg32 rng(3, 5);
    while (values.size() < 3000) values.push_back(1.1f * rng.next_float());
    for (const SimdLevel level : supported_simd_levels())
        for (const size_t n : {values.size() / 3, size_t{17}, size_t{15}, size_t{1}}) {
            SCOPED_TRACE(simd_level_name(level));
            // Channels from rotations of the values, so every value visits every channel.
            const float* red = values.data();
            const float* green = values.data() + values.size() / 3;
            const float* blue = values.data() + 2 * (values.size() / 3);
            std::vector<uint8_t> rgb(3 * n);
            encoder.encode_row(red, green, blue, n, rgb.data(), level);
            for (size_t i = 0; i < n; ++i) {
                ASSERT_EQ(rgb[3 * i], encoder.encode(red[i])) << red[i];
                ASSERT_EQ(rgb[3 * i + 1], encoder.encode(green[i])) << green[i];
                ASSERT_EQ(rgb[3 * i + 2], encoder.encode(blue[i])) << blue[i];
            }
        }
}

}  // namespace
}  // namespace hikari
