#include "hikari/frame/film.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "hikari/core/rng.h"
#include "hikari/core/srgb8_encoder.h"

namespace hikari {
namespace {

/// A row of colours around [0, 1], with values below, above, and not numbers at all.
std::vector<Vec3> test_row(Pcg32& rng, int width) {
    std::vector<Vec3> row(static_cast<size_t>(width));
    for (Vec3& c : row)
        for (int k = 0; k < 3; ++k) c[k] = 1.2f * rng.next_float() - 0.1f;
    row[0] = Vec3(std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                  -std::numeric_limits<float>::infinity());
    return row;
}

/// The same row written to `film`, once as colours and once as one array per channel, alternating
/// by row; the last pixel by set_pixel.
void write_rows(Film& film, uint64_t seed) {
    Pcg32 rng(seed, 7);
    const auto width = static_cast<size_t>(film.width());
    for (int y = 0; y < film.height(); ++y) {
        const std::vector<Vec3> row = test_row(rng, film.width());
        const size_t first = static_cast<size_t>(y) * width;
        if (y % 2 == 0) {
            film.set_row(first, row.data(), width);
            continue;
        }
        std::vector<float> r, g, b;
        for (const Vec3& c : row) r.push_back(c.x), g.push_back(c.y), b.push_back(c.z);
        film.set_row(first, r.data(), g.data(), b.data(), width);
    }
    film.set_pixel(width * film.height() - 1, Vec3(0.25f, 0.5f, 0.75f));
}

TEST(Film, Srgb8RowsAreTheLinearRowsEncoded) {
    // 37 wide: the row encoders' SIMD blocks and their remainders.
    Film linear(37, 5, FilmFormat::linear), srgb8(37, 5, FilmFormat::srgb8);
    write_rows(linear, 11);
    write_rows(srgb8, 11);
    EXPECT_EQ(srgb8.format(), FilmFormat::srgb8);
    ASSERT_EQ(srgb8.width(), 37);
    ASSERT_EQ(srgb8.height(), 5);
    EXPECT_TRUE(srgb8.linear().pixels.empty());
    EXPECT_TRUE(linear.srgb8().bytes.empty());
    EXPECT_EQ(srgb8.srgb8().bytes, encode_srgb8(linear.linear()).bytes);
}

TEST(Film, LinearFilmKeepsTheColoursExactly) {
    Film film(3, 2, FilmFormat::linear);
    const Vec3 row[3] = {Vec3(-1.0f), Vec3(0.5f, 2.0f, 7.0f), Vec3(1e-30f)};
    film.set_row(3, row, 3);
    EXPECT_EQ(film.linear().at(0, 1), row[0]);
    EXPECT_EQ(film.linear().at(1, 1), row[1]);
    EXPECT_EQ(film.linear().at(2, 1), row[2]);
}

}  // namespace
}  // namespace hikari
