#include "hikari/core/sobol.h"

#include <set>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace hikari {
namespace {

TEST(Sobol, ReverseBitsMirrorsTheWord) {
    EXPECT_EQ(reverse_bits(1U), 0x80000000U);
    EXPECT_EQ(reverse_bits(0x80000000U), 1U);
    EXPECT_EQ(reverse_bits(0x0000ff01U), 0x80ff0000U);
}

TEST(Sobol, FirstDimensionsAreTheUnscrambledSequence) {
    // Sobol' (0, 2)-sequence: 0, 1/2, 1/4 and 3/4, 3/4 and 1/4, ...
    EXPECT_EQ(sobol_dimension0(1), 0x80000000U);
    EXPECT_EQ(sobol_dimension1(1), 0x80000000U);
    EXPECT_EQ(sobol_dimension0(2), 0x40000000U);
    EXPECT_EQ(sobol_dimension1(2), 0xc0000000U);
    EXPECT_EQ(sobol_dimension0(3), 0xc0000000U);
    EXPECT_EQ(sobol_dimension1(3), 0x40000000U);
}

/// Whether every elementary interval of area 1/n (n = 2^k, boxes 2^a × 2^(k−a)) holds exactly
/// one of the n points: the (0, 2)-net property Owen scrambling keeps.
bool is_02_net(const std::vector<Vec2>& points) {
    const int n = static_cast<int>(points.size());
    for (int cols = 1; cols <= n; cols *= 2) {
        const int rows = n / cols;
        std::set<std::pair<int, int>> cells;
        for (const Vec2& p : points)
            cells.insert({static_cast<int>(p.x * cols), static_cast<int>(p.y * rows)});
        if (static_cast<int>(cells.size()) != n) return false;
    }
    return true;
}

TEST(Sobol, EveryDimensionPairOfAPixelIsAScrambledNet) {
    for (uint32_t pixel : {0U, 7U, 123456U}) {
        for (int pair = 0; pair < 4; ++pair) {
            std::vector<Vec2> points;
            for (uint32_t i = 0; i < 64; ++i) {
                SobolSampler sampler(hash_u32(pixel), i);
                Vec2 p{};
                for (int d = 0; d <= pair; ++d) p = sampler.next_2d();
                EXPECT_GE(p.x, 0.0f);
                EXPECT_LT(p.x, 1.0f);
                points.push_back(p);
            }
            EXPECT_TRUE(is_02_net(points)) << "pixel " << pixel << " pair " << pair;
            // Also the first 16 alone (a prefix of a net of size 2^k is a net).
            EXPECT_TRUE(is_02_net({points.begin(), points.begin() + 16}));
        }
    }
}

TEST(Sobol, OneDimensionStratifiesToo) {
    std::set<int> cells;
    for (uint32_t i = 0; i < 32; ++i) {
        SobolSampler sampler(99, i);
        sampler.next_2d();
        cells.insert(static_cast<int>(sampler.next_1d() * 32));
    }
    EXPECT_EQ(cells.size(), 32U);
}

TEST(Sobol, PixelsAndPairsAreDecorrelated) {
    // The same index in two pixels, or two pairs of one pixel, gives different points.
    SobolSampler a(hash_u32(1), 5), b(hash_u32(2), 5);
    const Vec2 pa = a.next_2d(), pb = b.next_2d();
    EXPECT_NE(pa.x, pb.x);
    const Vec2 second = a.next_2d();
    EXPECT_NE(pa.x, second.x);
    // And the sequence is a pure function of (seed, index, dimension).
    SobolSampler again(hash_u32(1), 5);
    EXPECT_EQ(again.next_2d().x, pa.x);
}

}  // namespace
}  // namespace hikari
