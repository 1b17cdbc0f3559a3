#pragma once
// The pixel filter of a path-traced image: how much a sample at offset (dx, dy) from a pixel's
// centre counts toward that pixel. Samples are drawn with the filter's own density (filter
// importance sampling: Ernst et al. 2006), so each sample belongs to one pixel with weight 1 and
// a pixel's value is the mean of its samples: pixels stay independent of each other (and of the
// thread count), and a negative-free filter adds no noise of its own.

#include <string_view>
#include <vector>

#include "hikari/core/vec.h"

namespace hikari {

/// The filter's shape, separable: f(dx, dy) = f1(dx) f1(dy) over [−w/2, w/2]².
enum class PixelFilterKind {
    box,              ///< f1 = 1: the pixel's area (w = 1) or a wider square
    gaussian,         ///< f1 = exp(−x² / 2σ²), σ = w / 6, cut at ±w/2 (±3σ)
    blackman_harris,  ///< the 4-term Blackman–Harris window (Harris 1978), Cycles' default
};

/// The default width of each kind, in pixels: the pixel itself for the box, 1.5 for the others
/// (Cycles' default filter width).
float default_filter_width(PixelFilterKind kind);

/// Offsets from a pixel's centre drawn with the filter's density.
class PixelFilter {
  public:
    /// `width` > 0 in pixels: the filter's support is [−width/2, width/2]².
    explicit PixelFilter(PixelFilterKind kind = PixelFilterKind::box, float width = 1.0f);

    /// The offset (in pixels) for the point `u` of the unit square: u mapped through the
    /// inverse of the filter's cumulative distribution on each axis (stratification of u is
    /// kept: the map is monotonic).
    Vec2 offset(Vec2 u) const { return {offset_1d(u.x), offset_1d(u.y)}; }

    /// The one-axis filter f1 at x (pixels), not normalized: 0 outside the support.
    float weight_1d(float x) const;

    PixelFilterKind kind() const { return m_kind; }
    float width() const { return m_width; }

  private:
    float offset_1d(float u) const;

    PixelFilterKind m_kind;
    float m_width;
    /// The inverse cumulative distribution of f1, sampled at k_table + 1 evenly spaced
    /// probabilities (empty for the box, whose inverse is linear).
    std::vector<float> m_inverse_cdf;
};

}  // namespace hikari
