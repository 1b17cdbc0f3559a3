#include "hikari/core/piecewise_constant.h"

#include <algorithm>
#include <cmath>

namespace hikari {

PiecewiseConstant1D::PiecewiseConstant1D(std::span<const float> weights) {
    const size_t n = std::max<size_t>(weights.size(), 1);
    m_density.assign(n, 1.0f);
    m_cdf.assign(n + 1, 0.0);
    double sum = 0;
    for (size_t i = 0; i < weights.size(); ++i) {
        const float w = weights[i];
        sum += std::isfinite(w) && w > 0.0f ? w : 0.0f;
        m_cdf[i + 1] = sum;
    }
    if (!(sum > 0.0)) {  // nothing to prefer: uniform
        for (size_t i = 0; i <= n; ++i) m_cdf[i] = static_cast<double>(i) / static_cast<double>(n);
        m_integral = 0.0f;
        return;
    }
    m_integral = static_cast<float>(sum / static_cast<double>(n));
    for (size_t i = 0; i < n; ++i) {
        m_cdf[i + 1] /= sum;
        m_density[i] = static_cast<float>((m_cdf[i + 1] - m_cdf[i]) * static_cast<double>(n));
    }
    m_cdf[n] = 1.0;
}

float PiecewiseConstant1D::sample(float u, float& pdf, int& cell) const {
    // The last cdf entry not above u, among cells of nonzero probability.
    const auto it = std::upper_bound(m_cdf.begin(), m_cdf.end(), static_cast<double>(u));
    const int n = size();
    cell = std::clamp(static_cast<int>(it - m_cdf.begin()) - 1, 0, n - 1);
    while (m_density[static_cast<size_t>(cell)] == 0.0f && cell + 1 < n) ++cell;
    pdf = m_density[static_cast<size_t>(cell)];
    const double lo = m_cdf[static_cast<size_t>(cell)], hi = m_cdf[static_cast<size_t>(cell) + 1];
    const double within = hi > lo ? (static_cast<double>(u) - lo) / (hi - lo) : 0.5;
    const double x = (cell + std::clamp(within, 0.0, 1.0)) / n;
    return std::min(static_cast<float>(x), std::nextafter(1.0f, 0.0f));
}

PiecewiseConstant2D::PiecewiseConstant2D(std::span<const float> weights, int width, int height) {
    std::vector<float> row_means(static_cast<size_t>(height));
    m_rows.reserve(static_cast<size_t>(height));
    for (int y = 0; y < height; ++y) {
        m_rows.emplace_back(weights.subspan(static_cast<size_t>(y) * width, width));
        row_means[static_cast<size_t>(y)] = m_rows.back().integral();
    }
    m_marginal = PiecewiseConstant1D(row_means);
}

Vec2 PiecewiseConstant2D::sample(Vec2 xi, float& pdf) const {
    float pdf_row = 0, pdf_column = 0;
    int row = 0, column = 0;
    const float v = m_marginal.sample(xi.y, pdf_row, row);
    const float u = m_rows[static_cast<size_t>(row)].sample(xi.x, pdf_column, column);
    pdf = pdf_row * pdf_column;
    return {u, v};
}

float PiecewiseConstant2D::pdf(Vec2 uv) const {
    const int rows = m_marginal.size();
    const int row = std::clamp(static_cast<int>(uv.y * static_cast<float>(rows)), 0, rows - 1);
    const PiecewiseConstant1D& columns = m_rows[static_cast<size_t>(row)];
    const int column = std::clamp(static_cast<int>(uv.x * static_cast<float>(columns.size())), 0,
                                  columns.size() - 1);
    return m_marginal.pdf(row) * columns.pdf(column);
}

}  // namespace hikari
