#pragma once
// A uniform grid over the image holding the projected triangles that overlap each cell: which
// faces can hide a line, or pierce a face, are among those in the cells the line or face
// crosses.

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "hikari/core/vec.h"
#include "hikari/raster/screen_triangle.h"

namespace hikari {

class ScreenGrid {
  public:
    ScreenGrid() = default;
    /// Bins each of `triangles` into the cells (of `cell` pixels, > 0; fractions of a pixel
    /// allowed, for small images) its bounding box overlaps, in index order; the grid covers a
    /// width × height image, and what lies beyond it goes to the border cells.
    ScreenGrid(std::span<const ScreenTriangle> triangles, int width, int height, float cell);

    /// Bins `triangles` into about `cells` cells over the box [lo, hi] of the image plane
    /// (pixels), each triangle's box widened by `widen` × its larger side (so that a point just
    /// outside a triangle, within a tolerance relative to its size, still finds it); triangles
    /// whose widened box misses [lo, hi] are left out, the rest beyond it go to the border cells.
    /// The cells follow the scene, not the pixels: the same triangles give the same grid at any
    /// image size.
    ScreenGrid(std::span<const ScreenTriangle> triangles, Vec2 lo, Vec2 hi, size_t cells,
               float widen);

    /// The smaller side of a cell, in pixels.
    float cell_size() const { return std::min(m_cell_w, m_cell_h); }

    /// Calls visit(triangle index) for every triangle binned in a cell that the segment (a, b)
    /// passes within `reach` pixels of; a triangle in several such cells is visited once per
    /// cell.
    template <class Visit>
    void for_each_along(Vec2 a, Vec2 b, float reach, const Visit& visit) const {
        const float y_lo = std::min(a.y, b.y) - reach, y_hi = std::max(a.y, b.y) + reach;
        for (int gy = row_of(y_lo); gy <= row_of(y_hi); ++gy) {
            float x_lo, x_hi;
            x_range_in_row(a, b, reach, gy, x_lo, x_hi);
            for (int gx = column_of(x_lo); gx <= column_of(x_hi); ++gx) visit_cell(gx, gy, visit);
        }
    }

    /// Calls visit(triangle index) for every triangle binned in a cell overlapping the box.
    template <class Visit>
    void for_each_in_box(Vec2 lo, Vec2 hi, const Visit& visit) const {
        for (int gy = row_of(lo.y); gy <= row_of(hi.y); ++gy)
            for (int gx = column_of(lo.x); gx <= column_of(hi.x); ++gx) visit_cell(gx, gy, visit);
    }

  private:
    int column_of(float x) const;
    int row_of(float y) const;
    /// The x extent of the segment, widened by `reach`, within cell row gy.
    void x_range_in_row(Vec2 a, Vec2 b, float reach, int gy, float& x_lo, float& x_hi) const;

    template <class Visit>
    void visit_cell(int gx, int gy, const Visit& visit) const {
        const size_t c = static_cast<size_t>(gy) * m_columns + gx;
        for (uint32_t k = m_first[c]; k < m_first[c + 1]; ++k) visit(m_items[k]);
    }

    /// Fills the cells with the triangles whose (widened) boxes `keep` accepts.
    template <class Keep>
    void bin(std::span<const ScreenTriangle> triangles, float widen, const Keep& keep);

    Vec2 m_origin{0.0f, 0.0f};  ///< the corner of cell (0, 0), in pixels
    float m_cell_w = 8, m_cell_h = 8;
    int m_columns = 1, m_rows = 1;
    std::vector<uint32_t> m_first;  ///< per cell, where its triangles start in m_items
    std::vector<uint32_t> m_items;  ///< triangle indices, cell after cell
};

}  // namespace hikari
