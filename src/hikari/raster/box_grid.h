#pragma once
// A uniform grid of screen boxes that grows as boxes are added: which polygons of the depth
// sort can overlap one (raster/depth_sort.cpp) are among those in the cells its box covers, so
// a sort of many small polygons compares each with its neighbours, not with all the others.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace hikari {

/// An axis-aligned box in the image plane, in pixels.
struct ScreenBox {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

class BoxGrid {
  public:
    BoxGrid() = default;
    /// About `cells` square-ish cells over `bounds`; boxes reaching beyond it go to the border
    /// cells.
    BoxGrid(const ScreenBox& bounds, size_t cells) : m_bounds(bounds) {
        const double w = std::max(bounds.x1 - bounds.x0, 1e-30);
        const double h = std::max(bounds.y1 - bounds.y0, 1e-30);
        const double side = std::sqrt(static_cast<double>(std::max<size_t>(cells, 1)) * w / h);
        m_columns = static_cast<int>(std::clamp(side, 1.0, 4096.0));
        m_rows = static_cast<int>(
            std::clamp(static_cast<double>(std::max<size_t>(cells, 1)) / m_columns, 1.0, 4096.0));
        m_cell_w = w / m_columns;
        m_cell_h = h / m_rows;
        m_cells.resize(static_cast<size_t>(m_columns) * m_rows);
    }

    size_t cell_count() const { return m_cells.size(); }

    /// How many cells `box` covers.
    size_t cells_covered(const ScreenBox& box) const {
        return static_cast<size_t>(column_of(box.x1) - column_of(box.x0) + 1) *
               static_cast<size_t>(row_of(box.y1) - row_of(box.y0) + 1);
    }

    /// Adds `id` to every cell `box` covers.
    void insert(uint32_t id, const ScreenBox& box) {
        for_each_cell(box, [&](std::vector<uint32_t>& cell) { cell.push_back(id); });
    }

    /// Calls visit(id) for every id in a cell `box` covers (once per cell).
    template <class Visit>
    void for_each_in_box(const ScreenBox& box, const Visit& visit) const {
        for (int gy = row_of(box.y0); gy <= row_of(box.y1); ++gy)
            for (int gx = column_of(box.x0); gx <= column_of(box.x1); ++gx)
                for (const uint32_t id : m_cells[static_cast<size_t>(gy) * m_columns + gx])
                    visit(id);
    }

  private:
    int column_of(double x) const {
        const double g = std::floor((x - m_bounds.x0) / m_cell_w);
        return g > 0.0 ? static_cast<int>(std::min(g, double(m_columns - 1))) : 0;
    }
    int row_of(double y) const {
        const double g = std::floor((y - m_bounds.y0) / m_cell_h);
        return g > 0.0 ? static_cast<int>(std::min(g, double(m_rows - 1))) : 0;
    }
    template <class F>
    void for_each_cell(const ScreenBox& box, F&& f) {
        for (int gy = row_of(box.y0); gy <= row_of(box.y1); ++gy)
            for (int gx = column_of(box.x0); gx <= column_of(box.x1); ++gx)
                f(m_cells[static_cast<size_t>(gy) * m_columns + gx]);
    }

    ScreenBox m_bounds;
    int m_columns = 1, m_rows = 1;
    double m_cell_w = 1, m_cell_h = 1;
    std::vector<std::vector<uint32_t>> m_cells{1};
};

}  // namespace hikari
