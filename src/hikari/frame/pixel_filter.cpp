#include "hikari/frame/pixel_filter.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hikari {

namespace {

/// Entries of the inverse-CDF table; the filter is tabulated twice as finely.
constexpr int k_table = k_filter_table;
constexpr int k_fine = 4 * k_table;

}  // namespace

float default_filter_width(PixelFilterKind kind) {
    return kind == PixelFilterKind::box ? 1.0f : 1.5f;
}

PixelFilter::PixelFilter(PixelFilterKind kind, float width) : m_kind(kind), m_width(width) {
    if (kind == PixelFilterKind::box) return;
    // The cumulative integral of f1 over the support by the midpoint rule, then inverted at
    // evenly spaced probabilities by linear interpolation.
    std::vector<double> cdf(k_fine + 1, 0.0);
    const double step = static_cast<double>(width) / k_fine;
    for (int i = 0; i < k_fine; ++i) {
        const double x = -0.5 * width + (i + 0.5) * step;
        cdf[i + 1] = cdf[i] + std::max(0.0, static_cast<double>(weight_1d(static_cast<float>(x))));
    }
    const double total = cdf[k_fine];
    m_inverse_cdf.resize(k_table + 1);
    int i = 0;
    for (int k = 0; k <= k_table; ++k) {
        const double p = total * k / k_table;
        while (i < k_fine - 1 && cdf[i + 1] < p) ++i;
        const double span = cdf[i + 1] - cdf[i];
        const double t = span > 0.0 ? std::clamp((p - cdf[i]) / span, 0.0, 1.0) : 0.5;
        m_inverse_cdf[k] = static_cast<float>(-0.5 * width + (i + t) * step);
    }
}

float PixelFilter::weight_1d(float x) const {
    const float half = 0.5f * m_width;
    if (!(std::abs(x) <= half)) return 0.0f;
    switch (m_kind) {
        case PixelFilterKind::box:
            return 1.0f;
        case PixelFilterKind::gaussian: {
            const float sigma = m_width / 6.0f;
            return std::exp(-x * x / (2.0f * sigma * sigma));
        }
        case PixelFilterKind::blackman_harris: {
            // The window over [0, w] written about its centre: the odd terms change sign.
            constexpr float k_two_pi = 2.0f * std::numbers::pi_v<float>;
            const float phase = k_two_pi * x / m_width;
            return 0.35875f + 0.48829f * std::cos(phase) + 0.14128f * std::cos(2.0f * phase) +
                   0.01168f * std::cos(3.0f * phase);
        }
    }
    return 0.0f;
}

float PixelFilter::offset_1d(float u) const {
    return filter_offset_1d(m_inverse_cdf.empty() ? nullptr : m_inverse_cdf.data(), m_width, u);
}

}  // namespace hikari
