#pragma once
// The pixel filter of a path-traced image: how much a sample at offset (dx, dy) from a pixel's
// centre counts toward that pixel. Samples are drawn with the filter's own density (filter
// importance sampling: Ernst et al. 2006), so each sample belongs to one pixel with weight 1 and
// a pixel's value is the mean of its samples: pixels stay independent of each other (and of the
// thread count), and a negative-free filter adds no noise of its own.

#include <algorithm>
#include <span>
#include <string_view>
#include <vector>

#include "hikari/core/host_device.h"
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

/// Entries of a filter's inverse-CDF table (PixelFilter::inverse_cdf has one more).
inline constexpr int k_filter_table = 1024;

/// The one-axis offset (pixels) for the number `u` in [0, 1): through the filter's inverse CDF
/// `inverse_cdf` (k_filter_table + 1 values), linearly interpolated, or, for the box (null), the
/// linear map onto [−width/2, width/2]. PixelFilter's, and the GPU kernels' over their copy.
HIKARI_HD inline float filter_offset_1d(const float* inverse_cdf, float width, float u) {
    if (!inverse_cdf) return (u - 0.5f) * width;
    const float scaled = std::clamp(u, 0.0f, 1.0f) * k_filter_table;
    const int k = std::min(static_cast<int>(scaled), k_filter_table - 1);
    const float t = scaled - static_cast<float>(k);
    return inverse_cdf[k] + t * (inverse_cdf[k + 1] - inverse_cdf[k]);
}

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
    /// The inverse CDF filter_offset_1d reads (empty for the box).
    std::span<const float> inverse_cdf() const { return m_inverse_cdf; }
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
