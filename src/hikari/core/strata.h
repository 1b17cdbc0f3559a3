#pragma once
// Stratified sampling of the unit square: n samples, one in each cell of the most square grid
// cols × rows = n, each jittered inside its cell. Stratified samples converge faster than
// independent ones wherever the integrand is smooth within the cells (for a shadow edge across
// the square, the error falls as n^-3/4 instead of n^-1/2: Mitchell 1996, "Consequences of
// stratified sampling in graphics").

#include <cmath>

#include "hikari/core/rng.h"
#include "hikari/core/vec.h"

namespace hikari {

/// The most square grid cols × rows = n (cols <= rows).
inline void strata(int n, int& cols, int& rows) {
    cols = static_cast<int>(std::sqrt(static_cast<double>(n)));
    while (cols > 1 && n % cols != 0) --cols;
    cols = cols < 1 ? 1 : cols;
    rows = n / cols;
}

/// The n samples of one stratified pattern, drawn from a random stream.
class StratifiedSquare {
  public:
    StratifiedSquare(int n, Pcg32 stream) : m_stream(stream) { strata(n, m_cols, m_rows); }
    /// Sample k in [0, n): a point of cell (k mod cols, k div cols).
    Vec2 next(int k) {
        const float x = (static_cast<float>(k % m_cols) + m_stream.next_float()) / m_cols;
        const int row = k / m_cols;
        const float y = (static_cast<float>(row) + m_stream.next_float()) / m_rows;
        return {x, y};
    }

  private:
    Pcg32 m_stream;
    int m_cols = 1, m_rows = 1;
};

}  // namespace hikari
