#include "hikari/raster/screen_grid.h"

#include <algorithm>
#include <cmath>

namespace hikari {

namespace {

/// The bounding box of a projected triangle, in pixels, widened by `widen` × its larger side.
void bounds_of(const ScreenTriangle& t, float widen, float& x0, float& y0, float& x1, float& y1) {
    x0 = std::min({t.v[0].position.x, t.v[1].position.x, t.v[2].position.x});
    x1 = std::max({t.v[0].position.x, t.v[1].position.x, t.v[2].position.x});
    y0 = std::min({t.v[0].position.y, t.v[1].position.y, t.v[2].position.y});
    y1 = std::max({t.v[0].position.y, t.v[1].position.y, t.v[2].position.y});
    if (widen > 0.0f) {
        const float margin = widen * std::max(x1 - x0, y1 - y0);
        x0 -= margin, y0 -= margin, x1 += margin, y1 += margin;
    }
}

}  // namespace

ScreenGrid::ScreenGrid(std::span<const ScreenTriangle> triangles, int width, int height, float cell)
    : m_cell_w(cell > 0.0f ? cell : 1.0f),
      m_cell_h(m_cell_w),
      m_columns(std::max(1, static_cast<int>(std::ceil(static_cast<float>(width) / m_cell_w)))),
      m_rows(std::max(1, static_cast<int>(std::ceil(static_cast<float>(height) / m_cell_h)))) {
    bin(triangles, 0.0f, [](float, float, float, float) { return true; });
}

ScreenGrid::ScreenGrid(std::span<const ScreenTriangle> triangles, Vec2 lo, Vec2 hi, size_t cells,
                       float widen)
    : m_origin(lo) {
    const double w = std::max(double(hi.x) - lo.x, 1e-30), h = std::max(double(hi.y) - lo.y, 1e-30);
    const double n = static_cast<double>(std::max<size_t>(cells, 1));
    const double columns = std::clamp(std::sqrt(n * w / h), 1.0, 8192.0);
    m_columns = static_cast<int>(columns);
    m_rows = static_cast<int>(std::clamp(n / m_columns, 1.0, 8192.0));
    m_cell_w = static_cast<float>(w / m_columns);
    m_cell_h = static_cast<float>(h / m_rows);
    if (!(m_cell_w > 0.0f) || !std::isfinite(m_cell_w)) m_cell_w = 1.0f, m_columns = 1;
    if (!(m_cell_h > 0.0f) || !std::isfinite(m_cell_h)) m_cell_h = 1.0f, m_rows = 1;
    bin(triangles, widen, [&](float x0, float y0, float x1, float y1) {
        return x1 >= lo.x && x0 <= hi.x && y1 >= lo.y && y0 <= hi.y;
    });
}

template <class Keep>
void ScreenGrid::bin(std::span<const ScreenTriangle> triangles, float widen, const Keep& keep) {
    const size_t cells = static_cast<size_t>(m_columns) * m_rows;
    m_first.assign(cells + 1, 0);
    // Two passes, counting then filling, so that each cell lists its triangles in index order.
    auto for_each_cell = [&](const ScreenTriangle& t, auto&& f) {
        float x0, y0, x1, y1;
        bounds_of(t, widen, x0, y0, x1, y1);
        if (!keep(x0, y0, x1, y1)) return;
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
    const float g = std::floor((x - m_origin.x) / m_cell_w);
    return g > 0.0f ? static_cast<int>(std::min(g, float(m_columns - 1))) : 0;
}

int ScreenGrid::row_of(float y) const {
    const float g = std::floor((y - m_origin.y) / m_cell_h);
    return g > 0.0f ? static_cast<int>(std::min(g, float(m_rows - 1))) : 0;
}

void ScreenGrid::x_range_in_row(Vec2 a, Vec2 b, float reach, int gy, float& x_lo,
                                float& x_hi) const {
    // Rows at the border also hold everything beyond the grid.
    const float y0 = gy == 0 ? -INFINITY : m_origin.y + static_cast<float>(gy) * m_cell_h - reach;
    const float y1 =
        gy == m_rows - 1 ? INFINITY : m_origin.y + static_cast<float>(gy + 1) * m_cell_h + reach;
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
