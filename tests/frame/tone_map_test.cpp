#include "hikari/frame/tone_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "../io/temp_dir.h"
#include "hikari/core/srgb8_encoder.h"
#include "hikari/io/images/image_write.h"

namespace hikari {
namespace {

constexpr float k_inf = std::numeric_limits<float>::infinity();

TEST(ToneMap, ClampLeavesValuesToTheEncoder) {
    for (const float c : {-1.0f, 0.0f, 0.25f, 1.0f, 7.0f, k_inf})
        EXPECT_EQ(tone_map(c, ToneMap::clamp), c);
}

TEST(ToneMap, ReinhardIsCOverOnePlusC) {
    EXPECT_EQ(tone_map(0.0f, ToneMap::reinhard), 0.0f);
    EXPECT_FLOAT_EQ(tone_map(1.0f, ToneMap::reinhard), 0.5f);
    EXPECT_FLOAT_EQ(tone_map(3.0f, ToneMap::reinhard), 0.75f);
    EXPECT_NEAR(tone_map(1e6f, ToneMap::reinhard), 1.0f, 1e-5f);
    EXPECT_EQ(tone_map(k_inf, ToneMap::reinhard), 1.0f);
    EXPECT_EQ(tone_map(-2.0f, ToneMap::reinhard), 0.0f);
    EXPECT_EQ(tone_map(NAN, ToneMap::reinhard), 0.0f);
}

TEST(ToneMap, AcesFollowsNarkowiczsCurve) {
    EXPECT_EQ(tone_map(0.0f, ToneMap::aces), 0.0f);
    // (2.51 + 0.03) / (2.43 + 0.59 + 0.14) at 1; 0.5: (0.5 · 1.285) / (0.5 · 1.805 + 0.14).
    EXPECT_NEAR(tone_map(1.0f, ToneMap::aces), 2.54f / 3.16f, 1e-6f);
    EXPECT_NEAR(tone_map(0.5f, ToneMap::aces), 0.6425f / 1.0425f, 1e-6f);
    // The fitted curve passes 1 near 7.3 and is clamped there.
    EXPECT_LT(tone_map(7.0f, ToneMap::aces), 1.0f);
    EXPECT_EQ(tone_map(8.0f, ToneMap::aces), 1.0f);
    EXPECT_EQ(tone_map(1e30f, ToneMap::aces), 1.0f);
    EXPECT_EQ(tone_map(k_inf, ToneMap::aces), 1.0f);
    EXPECT_EQ(tone_map(-1.0f, ToneMap::aces), 0.0f);
    EXPECT_EQ(tone_map(NAN, ToneMap::aces), 0.0f);
}

TEST(ToneMap, OperatorsAreMonotonic) {
    for (const ToneMap op : {ToneMap::reinhard, ToneMap::aces}) {
        float last = 0.0f;
        for (float c = 0.001f; c < 100.0f; c *= 1.1f) {
            const float v = tone_map(c, op);
            EXPECT_GE(v, last) << c;
            last = v;
        }
    }
}

TEST(ToneMap, ExposureDoublesPerStop) {
    Image image(2, 1);
    image.at(0, 0) = {0.1f, 0.2f, 3.0f};
    image.at(1, 0) = {-0.5f, 0.0f, 1e-3f};
    Image brighter = image;
    expose_and_tone_map(brighter, 1.0f, ToneMap::clamp);
    Image darker = image;
    expose_and_tone_map(darker, -2.0f, ToneMap::clamp);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(brighter.pixels[i][c], 2.0f * image.pixels[i][c]);
            EXPECT_EQ(darker.pixels[i][c], 0.25f * image.pixels[i][c]);
        }
}

TEST(ToneMap, ExposureComesBeforeTheOperator) {
    Image image(1, 1, Vec3(0.5f));
    expose_and_tone_map(image, 1.0f, ToneMap::reinhard);  // 0.5 · 2 = 1, then 1 / 2
    EXPECT_FLOAT_EQ(image.at(0, 0).x, 0.5f);
}

TEST(ToneMap, DefaultsWriteTodaysBytes) {
    testing::TempDir dir;
    Image image(40, 33);  // ramps past 1 and below 0, so the encoder's clamping shows
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            image.at(x, y) = {0.05f * x - 0.2f, 0.1f * y, static_cast<float>((x * y) % 7) / 3.0f};
    Image developed = image;
    expose_and_tone_map(developed, 0.0f, ToneMap::clamp);
    for (const char* name : {"a.png", "a.ppm", "a.jpg", "a.pfm"}) {
        write_image(dir / (std::string("before-") + name), image);
        write_image(dir / (std::string("after-") + name), developed);
        EXPECT_EQ(testing::read_text(dir / (std::string("before-") + name)),
                  testing::read_text(dir / (std::string("after-") + name)))
            << name;
    }
    // Reinhard changes the picture (so the comparison above could fail).
    expose_and_tone_map(developed, 0.0f, ToneMap::reinhard);
    EXPECT_NE(encode_srgb8(developed).bytes, encode_srgb8(image).bytes);
}

}  // namespace
}  // namespace hikari
