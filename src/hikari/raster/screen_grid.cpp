#include "hikari/raster/screen_grid.h"

#include <algorithm>
#include <cmath>

namespace hikari {

namespace {

/// The bounding box of a projected triangle, in pixels.
void bounds_of(const ScreenTriangle& t, float& x0, float& y0, float& x1, float& y1) {
    x0 = std::min({t.v[0].position.x, t.v[1].position.x, t.v[2].position.x});
    x1 = std::max({t.v[0].position.x, t.v[1].position.x, t.v[2].position.x});
    y0 = std::min({t.v[0].position.y, t.v[1].position.y, t.v[2].position.y});
    y1 = std::max({t.v[0].position.y, t.v[1].position.y, t.v[2].position.y});
}

}  // namespace

ScreenGrid::ScreenGrid(std::span<const ScreenTriangle> triangles, int width, int height, float cell)
    : m_cell(cell > 0.0f ? cell : 1.0f),
      m_columns(std::max(1, static_cast<int>(std::ceil(static_cast<float>(width) / m_cell)))),
      m_rows(std::max(1, static_cast<int>(std::ceil(static_cast<float>(height) / m_cell)))) {
    const size_t cells = static_cast<size_t>(m_columns) * m_rows;
    m_first.assign(cells + 1, 0);
    // Two passes, counting then filling, so that each cell lists its triangles in index order.
    auto for_each_cell = [&](const ScreenTriangle& t, auto&& f) {
        float x0, y0, x1, y1;
        bounds_of(t, x0, y0, x1, y1);
        for (int gy = row_of(y0); gy <= row_of(y1); ++gy)
            for (int gx = column_of(x0); gx <= column_of(x1); ++gx)
                f(static_cast<size_t>(gy) * m_columns + gx);
    };
    for (const ScreenTriangle& t : triangles) for_each_cell(t, [&](size_t c) { ++m_first[c + 1]; });
    for (size_t c = 0; c < cells; ++c) m_first[c + 1] += m_first[c];
    m_items.resize(m_first[cells]);
    std::vector<uint32_t> next(m_first.begin(), m_first.end() - 1);
    for (uint32_t i = 0; i < triangles.size(); ++i)
        for_each_cell(triangles[i], [&](size_t c) { m_items[next[c]++] = i; });
}

int ScreenGrid::column_of(float x) const {
    const float g = std::floor(x / m_cell);
    return static_cast<int>(std::clamp(g, 0.0f, float(m_columns - 1)));
}

int ScreenGrid::row_of(float y) const {
    const float g = std::floor(y / m_cell);
    return static_cast<int>(std::clamp(g, 0.0f, float(m_rows - 1)));
}

void ScreenGrid::x_range_in_row(Vec2 a, Vec2 b, float reach, int gy, float& x_lo,
                                float& x_hi) const {
    // Rows at the border also hold everything beyond the image.
    const float y0 = gy == 0 ? -INFINITY : static_cast<float>(gy) * m_cell - reach;
    const float y1 = gy == m_rows - 1 ? INFINITY : static_cast<float>(gy + 1) * m_cell + reach;
    float s0 = 0.0f, s1 = 1.0f;
    const float dy = b.y - a.y;
    if (std::abs(dy) > 1e-12f) {
        float p = (y0 - a.y) / dy, q = (y1 - a.y) / dy;
        if (p > q) std::swap(p, q);
        s0 = std::max(s0, p);
        s1 = std::min(s1, q);
    }
    if (s0 > s1) s0 = s1 = std::clamp(0.5f * (s0 + s1), 0.0f, 1.0f);
    const float xa = a.x + (b.x - a.x) * s0, xb = a.x + (b.x - a.x) * s1;
    x_lo = std::min(xa, xb) - reach;
    x_hi = std::max(xa, xb) + reach;
}

}  // namespace hikari
