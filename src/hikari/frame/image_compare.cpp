#include "hikari/frame/image_compare.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hikari/core/color.h"

namespace hikari {

namespace {

/// Channel `c` of pixel `i` as an encoded value in [0, 1], rounded to 8 bits when asked.
double encoded(const Image& image, size_t i, int c, bool eight_bit) {
    const double v = linear_to_srgb(image.pixels[i][c]);
    return eight_bit ? std::round(v * 255.0) / 255.0 : v;
}

/// |a − b| of channel `c` of pixel `i` in encoded values: 0 where both are NaN (the same
/// non-value), 1 where only one is (as far apart as encoded values go).
double channel_difference(const Image& a, const Image& b, size_t i, int c, bool eight_bit) {
    const bool nan_a = std::isnan(a.pixels[i][c]), nan_b = std::isnan(b.pixels[i][c]);
    if (nan_a || nan_b) return nan_a && nan_b ? 0.0 : 1.0;
    return std::abs(encoded(a, i, c, eight_bit) - encoded(b, i, c, eight_bit));
}

/// Whether channel `c` of pixel `i` differs by more than `tolerance` in linear values, with NaN
/// equal to NaN and an infinity to the same infinity.
bool channel_differs(const Image& a, const Image& b, size_t i, int c, float tolerance) {
    const float x = a.pixels[i][c], y = b.pixels[i][c];
    if (std::isnan(x) || std::isnan(y)) return std::isnan(x) != std::isnan(y);
    return x != y && !(std::abs(x - y) <= tolerance);
}

bool has_nan(const Vec3& v) { return std::isnan(v.x) || std::isnan(v.y) || std::isnan(v.z); }

/// The largest encoded channel difference of pixel i.
double pixel_difference(const Image& a, const Image& b, size_t i, bool eight_bit) {
    double d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, channel_difference(a, b, i, c, eight_bit));
    return d;
}

}  // namespace

ImageDifference compare_images(const Image& a, const Image& b, bool eight_bit, float tolerance) {
    ImageDifference out;
    out.pixels = a.pixels.size();
    double squares = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        bool differs = false;
        for (int c = 0; c < 3; ++c) {
            const double d = channel_difference(a, b, i, c, eight_bit);
            squares += d * d;
            if (d > out.max_difference) {
                out.max_difference = d;
                out.max_x = static_cast<int>(i % static_cast<size_t>(a.width));
                out.max_y = static_cast<int>(i / static_cast<size_t>(a.width));
            }
            differs |= channel_differs(a, b, i, c, tolerance);
        }
        out.differing += differs ? 1 : 0;
        out.not_a_number_a += has_nan(a.pixels[i]) ? 1 : 0;
        out.not_a_number_b += has_nan(b.pixels[i]) ? 1 : 0;
    }
    const double mse = squares / (3.0 * static_cast<double>(std::max<size_t>(1, out.pixels)));
    out.psnr_db = mse > 0 ? 10.0 * std::log10(1.0 / mse) : std::numeric_limits<double>::infinity();
    return out;
}

Image difference_image(const Image& a, const Image& b, double scale) {
    // The ramp's stops in encoded sRGB: black, blue, red, yellow.
    constexpr Vec3 k_stops[4] = {{0, 0, 0}, {0.1f, 0.2f, 1}, {1, 0.1f, 0.1f}, {1, 1, 0.2f}};
    Image out(a.width, a.height);
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        const double d = pixel_difference(a, b, i, false);
        const double t = scale > 0 ? std::clamp(d / scale, 0.0, 1.0) * 3.0 : (d > 0 ? 3.0 : 0.0);
        const int k = std::min(2, static_cast<int>(t));
        const auto f = static_cast<float>(t - k);
        const Vec3 c = k_stops[k] + f * (k_stops[k + 1] - k_stops[k]);
        out.pixels[i] = {srgb_to_linear(c.x), srgb_to_linear(c.y), srgb_to_linear(c.z)};
    }
    return out;
}

}  // namespace hikari
