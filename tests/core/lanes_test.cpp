// The SIMD packs that shading code is written over: each operation is the float operation lane
// by lane, to the bit, and the helpers (select, any, for_each_distinct) behave as their scalar
// forms do.
#include "hikari/core/lanes.h"

#include <bit>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "hikari/core/rng.h"

namespace hikari {
namespace {

struct TestIsa {};
using Floats = LaneFloat<TestIsa>;
using Ints = LaneInt<TestIsa>;
using Masks = LaneMask<TestIsa>;

/// Random floats with the awkward ones among them: zeros of both signs, infinities, NaN, tiny.
Floats awkward_floats(Pcg32& rng) {
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

bool same_bits(float a, float b) {
    return std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b);
}

TEST(Lanes, ArithmeticIsTheFloatArithmeticLaneByLane) {
    Pcg32 rng(3, 1);
    for (int round = 0; round < 200; ++round) {
        const Floats a = awkward_floats(rng), b = awkward_floats(rng);
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

TEST(Lanes, ConversionsAndBitsMatchTheScalarForms) {
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

TEST(Lanes, AnyAndLaneBitsSeeEveryLane) {
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

TEST(Lanes, ForEachDistinctVisitsEachValueOnceWithItsLanes) {
    int32_t values[k_lanes];
    for (int i = 0; i < k_lanes; ++i) values[i] = (i * 7) % 3 + 10;
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
