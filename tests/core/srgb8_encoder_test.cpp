#include "hikari/core/srgb8_encoder.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

#include "hikari/core/color.h"

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

}  // namespace
}  // namespace hikari
