#pragma once
// Piecewise-constant probability densities on [0, 1) and [0, 1)², sampled by inverting their
// cumulative distributions: the importance sampling of environment maps (a 2-D density over the
// map's texels: a marginal density of rows, and one conditional density of columns per row).

#include <span>
#include <vector>

#include "hikari/core/vec.h"

namespace hikari {

/// A density on [0, 1) proportional to `weights[i]` on the i-th of n equal cells.
class PiecewiseConstant1D {
  public:
    PiecewiseConstant1D() = default;
    /// Negative or non-finite weights count as 0. All zero: the uniform density.
    explicit PiecewiseConstant1D(std::span<const float> weights);

    /// The point x in [0, 1) whose cumulative probability is `u` in [0, 1); `pdf` receives the
    /// density there and `cell` the cell it lies in.
    float sample(float u, float& pdf, int& cell) const;
    /// The density in cell `cell`.
    float pdf(int cell) const { return m_density[static_cast<size_t>(cell)]; }
    int size() const { return static_cast<int>(m_density.size()); }
    /// The mean of the weights (the integral of the unnormalized function over [0, 1)).
    float integral() const { return m_integral; }

  private:
    std::vector<float> m_density;  ///< per cell: weight / integral
    std::vector<double> m_cdf;     ///< n + 1 entries, 0 to 1
    float m_integral = 0;
};

/// A density on [0, 1)² proportional to `weights[row · width + column]` on a grid of
/// `width` × `height` equal cells (row 0 at v in [0, 1 / height)).
class PiecewiseConstant2D {
  public:
    PiecewiseConstant2D() = default;
    PiecewiseConstant2D(std::span<const float> weights, int width, int height);

    /// The point (u, v) for the random pair `xi`, and its density.
    Vec2 sample(Vec2 xi, float& pdf) const;
    /// The density at (u, v) in [0, 1)².
    float pdf(Vec2 uv) const;

  private:
    std::vector<PiecewiseConstant1D> m_rows;  ///< each row's density of columns
    PiecewiseConstant1D m_marginal;           ///< the density of rows
};

}  // namespace hikari
