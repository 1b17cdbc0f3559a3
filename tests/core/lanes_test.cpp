// The SIMD packs that shading code is written over: each operation is the float operation lane
// by lane, to the bit, and the helpers (select, any, for_each_distinct) behave as their scalar
// forms do.
#include "hikari/core/lanes.h"

#include <bit>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "../support/same_bits.h"
#include "hikari/core/rng.h"
#include "test_isa.h"

namespace hikari {
namespace {

using testing::same_bits;
using testing::TestIsa;

template <class Isa>
class Lanes : public ::testing::Test {
  protected:
    using Floats = LaneFloat<Isa>;
    using Ints = LaneInt<Isa>;
    using Masks = LaneMask<Isa>;
    static constexpr int k_lanes = Isa::k_width;
};
/// Packs of every width the kernels use: 4 (SSE), 8 (AVX2), 16 (AVX-512).
using Widths = ::testing::Types<TestIsa<4>, TestIsa<8>, TestIsa<16>>;
TYPED_TEST_SUITE(Lanes, Widths);

/// Random floats with the awkward ones among them: zeros of both signs, infinities, NaN, tiny.
template <class Floats>
Floats awkward_floats(Pcg32& rng) {
    constexpr int k_lanes = Floats::k_width;
    const float special[] = {0.0f,
                             -0.0f,
                             std::numeric_limits<float>::infinity(),
                             -std::numeric_limits<float>::infinity(),
                             std::numeric_limits<float>::quiet_NaN(),
                             1e-40f,
                             -1.0f,
                             1.0f};
    float values[k_lanes];
    for (float& v : values)
        v = rng.next_float() < 0.25f ? special[rng.next_u32() % 8]
                                     : (rng.next_float() - 0.5f) * 1000.0f;
    return Floats::load(values);
}

TYPED_TEST(Lanes, ArithmeticIsTheFloatArithmeticLaneByLane) {
    Pcg32 rng(3, 1);
    for (int round = 0; round < 200; ++round) {
        using Floats = typename TestFixture::Floats;
        using Masks = typename TestFixture::Masks;
        constexpr int k_lanes = TestFixture::k_lanes;
        const Floats a = awkward_floats<Floats>(rng), b = awkward_floats<Floats>(rng);
        const Floats sum = a + b, difference = a - b, product = a * b, quotient = a / b;
        const Floats root = sqrt_of(a), magnitude = abs_of(a), negated = -a;
        const Masks less = a < b;
        const Floats chosen = select(less, a, b);
        for (int i = 0; i < k_lanes; ++i) {
            ASSERT_TRUE(same_bits(sum[i], a[i] + b[i]));
            ASSERT_TRUE(same_bits(difference[i], a[i] - b[i]));
            ASSERT_TRUE(same_bits(product[i], a[i] * b[i]));
            ASSERT_TRUE(same_bits(quotient[i], a[i] / b[i]));
            ASSERT_TRUE(same_bits(root[i], std::sqrt(a[i])) ||
                        (std::isnan(root[i]) && std::isnan(std::sqrt(a[i]))));
            ASSERT_TRUE(same_bits(magnitude[i], std::fabs(a[i])) || std::isnan(a[i]));
            ASSERT_TRUE(same_bits(negated[i], -a[i]));
            ASSERT_EQ(less[i], a[i] < b[i]);
            ASSERT_TRUE(same_bits(chosen[i], select(a[i] < b[i], a[i], b[i])));
        }
    }
}

TYPED_TEST(Lanes, ConversionsAndBitsMatchTheScalarForms) {
    using Floats = typename TestFixture::Floats;
    using Ints = typename TestFixture::Ints;
    constexpr int k_lanes = TestFixture::k_lanes;
    float values[k_lanes];
    for (int i = 0; i < k_lanes; ++i) values[i] = (static_cast<float>(i) - 7.5f) * 3.3f;
    const Floats a = Floats::load(values);
    const Ints truncated = truncate_to_int(a), bits = float_bits(a);
    const Floats back = to_float(truncated), same = bits_float(bits);
    for (int i = 0; i < k_lanes; ++i) {
        EXPECT_EQ(truncated[i], static_cast<int32_t>(values[i]));
        EXPECT_EQ(bits[i], std::bit_cast<int32_t>(values[i]));
        EXPECT_EQ(back[i], static_cast<float>(static_cast<int32_t>(values[i])));
        EXPECT_TRUE(same_bits(same[i], values[i]));
    }
}

TYPED_TEST(Lanes, AnyAndLaneBitsSeeEveryLane) {
    using Masks = typename TestFixture::Masks;
    constexpr int k_lanes = TestFixture::k_lanes;
    for (int lane = 0; lane < k_lanes; ++lane) {
        int32_t flags[k_lanes] = {};
        flags[lane] = 1;
        const Masks one = Masks::load(flags);
        EXPECT_TRUE(any(one));
        EXPECT_EQ(lane_bits(one), 1u << lane);
    }
    EXPECT_FALSE(any(Masks(false)));
    EXPECT_EQ(lane_bits(Masks(true)), (1u << k_lanes) - 1);
}

TYPED_TEST(Lanes, ForEachDistinctVisitsEachValueOnceWithItsLanes) {
    using Ints = typename TestFixture::Ints;
    using Masks = typename TestFixture::Masks;
    constexpr int k_lanes = TestFixture::k_lanes;
    int32_t values[k_lanes];
    for (int i = 0; i < k_lanes; ++i) values[i] = (i * 7) % 3 + 10;  // 10, 11, 12, 10, ...
    std::vector<int32_t> seen;
    uint32_t covered = 0;
    for_each_distinct(Ints::load(values), [&](int32_t value, const Masks& lanes, bool first) {
        EXPECT_EQ(first, seen.empty());
        seen.push_back(value);
        for (int i = 0; i < k_lanes; ++i) EXPECT_EQ(lanes[i], values[i] == value);
        EXPECT_EQ(covered & lane_bits(lanes), 0u);
        covered |= lane_bits(lanes);
    });
    EXPECT_EQ(seen, (std::vector<int32_t>{10, 11, 12}));  // in order of first appearance
    EXPECT_EQ(covered, (1u << k_lanes) - 1);
    int calls = 0;
    for_each_distinct(int32_t{4}, [&](int32_t value, bool lanes, bool first) {
        EXPECT_EQ(value, 4);
        EXPECT_TRUE(lanes && first);
        ++calls;
    });
    EXPECT_EQ(calls, 1);
}

}  // namespace
}  // namespace hikari
