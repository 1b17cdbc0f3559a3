#include "hikari/frame/pixel_filter.h"

#include <cmath>

#include <gtest/gtest.h>

namespace hikari {
namespace {

TEST(PixelFilter, BoxSpreadsSamplesEvenlyOverThePixel) {
    const PixelFilter box;
    EXPECT_FLOAT_EQ(box.offset({0.0f, 0.5f}).x, -0.5f);
    EXPECT_FLOAT_EQ(box.offset({0.0f, 0.5f}).y, 0.0f);
    EXPECT_FLOAT_EQ(box.offset({0.75f, 1.0f}).x, 0.25f);
    const PixelFilter wide(PixelFilterKind::box, 2.0f);
    EXPECT_FLOAT_EQ(wide.offset({1.0f, 0.0f}).x, 1.0f);
}

/// The offsets a filter draws for evenly spaced u follow its own weights: the share of offsets
/// in each bin matches the bin's share of the filter's integral.
void expect_offsets_follow_weights(PixelFilterKind kind, float width) {
    const PixelFilter filter(kind, width);
    constexpr int k_bins = 12, k_draws = 120000;
    int counts[k_bins] = {};
    for (int i = 0; i < k_draws; ++i) {
        const float x = filter.offset({(i + 0.5f) / k_draws, 0.5f}).x;
        ASSERT_GE(x, -0.5f * width);
        ASSERT_LE(x, 0.5f * width);
        counts[std::min(k_bins - 1, static_cast<int>((x / width + 0.5f) * k_bins))]++;
    }
    double weights[k_bins] = {}, total = 0.0;
    for (int b = 0; b < k_bins; ++b) {
        for (int s = 0; s < 200; ++s) {
            const float x = width * ((b + (s + 0.5f) / 200.0f) / k_bins - 0.5f);
            weights[b] += filter.weight_1d(x);
        }
        total += weights[b];
    }
    for (int b = 0; b < k_bins; ++b)
        EXPECT_NEAR(static_cast<double>(counts[b]) / k_draws, weights[b] / total, 2e-3)
            << "bin " << b;
}

TEST(PixelFilter, GaussianAndBlackmanHarrisDrawOffsetsWithTheirDensity) {
    expect_offsets_follow_weights(PixelFilterKind::gaussian, 1.5f);
    expect_offsets_follow_weights(PixelFilterKind::blackman_harris, 1.5f);
    expect_offsets_follow_weights(PixelFilterKind::blackman_harris, 3.0f);
}

TEST(PixelFilter, WeightsPeakAtTheCentreAndVanishOutside) {
    const PixelFilter bh(PixelFilterKind::blackman_harris, 1.5f);
    EXPECT_NEAR(bh.weight_1d(0.0f), 1.0f, 1e-5f);
    EXPECT_NEAR(bh.weight_1d(0.75f), 0.0f, 1e-4f);  // the window's end: a0 − a1 + a2 − a3 ≈ 0
    EXPECT_EQ(bh.weight_1d(0.8f), 0.0f);
    EXPECT_FLOAT_EQ(default_filter_width(PixelFilterKind::box), 1.0f);
    EXPECT_FLOAT_EQ(default_filter_width(PixelFilterKind::gaussian), 1.5f);
}

}  // namespace
}  // namespace hikari
