#include "hikari/frame/framebuffer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace hikari {
namespace {

TEST(Framebuffer, RefusesAFilmOfAnotherSize) {
    EXPECT_THROW(Framebuffer(Film(4, 3, FilmFormat::linear), 4, 4, true), std::invalid_argument);
}

TEST(Framebuffer, AovBuffersAreTheFilmsSizeAndSayNothingSeen) {
    const Framebuffer fb(Film(4, 3, FilmFormat::srgb8), 4, 3, true);
    EXPECT_EQ(fb.width(), 4);
    EXPECT_EQ(fb.height(), 3);
    ASSERT_EQ(fb.depth.size(), 12u);
    EXPECT_TRUE(std::isinf(fb.depth[5]));
    EXPECT_EQ(fb.id[5], k_background_id);
    EXPECT_TRUE(Framebuffer(Film(4, 3, FilmFormat::linear), 4, 3, false).depth.empty());
}

TEST(Framebuffer, ColourAovNeedsALinearFilm) {
    Framebuffer eight_bit(Film(2, 2, FilmFormat::srgb8), 2, 2, false);
    EXPECT_THROW(aov_image(std::move(eight_bit), Aov::color), std::invalid_argument);
    Framebuffer linear(Film(2, 2, FilmFormat::linear), 2, 2, false);
    linear.set_color(3, Vec3(0.5f));
    EXPECT_EQ(aov_image(std::move(linear), Aov::color).at(1, 1), Vec3(0.5f));
}

}  // namespace
}  // namespace hikari
