#pragma once
// The solid checker (POV-Ray's `checker` pattern) at a surface point.

#include <cmath>

#include "hikari/core/lanes.h"
#include "hikari/scene/texture.h"
#include "hikari/shading/surface.h"
#include "hikari/shading/textures/lane_form.h"

namespace hikari {

/// The parity of floor(v): 1 where odd. Floats of 2^31 or more in magnitude are multiples of
/// 256, so even; below that floor is truncation stepped down for negative non-integers.
template <class F>
HIKARI_INLINE HIKARI_HD IntOf<F> floor_parity(F v) {
    const F w = select(abs_of(v) < F(2147483648.0f), v, F(0.0f));
    const IntOf<F> truncated = truncate_to_int(w);
    const IntOf<F> floor = truncated - select(w < to_float(truncated), IntOf<F>(1), IntOf<F>(0));
    return floor & IntOf<F>(1);
}

/// ∫₀ˣ s(t) dt for the square wave s(t) = (−1)^⌊t⌋: a triangle wave of period 2 (0 at even
/// integers, 1 at odd ones). `x` already reduced to [0, 2) keeps the difference below exact.
HIKARI_HD inline float square_wave_integral(float x) {
    const float m = x - 2.0f * std::floor(0.5f * x);
    return 1.0f - std::abs(1.0f - m);
}

/// s(t) = (−1)^⌊t⌋ averaged over [x − w/2, x + w/2]: the checker's one axis box-filtered over a
/// footprint w cells wide (Heckbert 1989's integrated square wave; Quilez's "filtered
/// checkerboard"). A footprint of many cells averages to 0, so far checkers fade to the mean
/// colour instead of beating into moiré; w = 0 is the sharp wave.
HIKARI_HD inline float filtered_square_wave(float x, float w) {
    const float sharp = floor_parity(x) != 0 ? -1.0f : 1.0f;
    // A box inside one cell averages the cell's own value: exactly, not by rounding.
    if (!(w > 1e-4f) || std::floor(x - 0.5f * w) == std::floor(x + 0.5f * w)) return sharp;
    if (w >= 2.0f * 65536.0f) return 0.0f;
    const float r = x - 2.0f * std::floor(0.5f * x);  // the same phase, near 0 where precise
    return (square_wave_integral(r + 0.5f * w) - square_wave_integral(r - 0.5f * w)) / w;
}

/// The checker is evaluated one point at a time: its filter needs the pixel's footprint, which
/// only the one-ray paths carry (as for image textures).
template <>
inline constexpr bool k_texture_has_lane_form<CheckerTexture> = false;

/// The checker's colour at `point`: colour_a where the cells' floor sum is even, else colour_b,
/// box-filtered over the pixel's footprint (SurfacePoint::dp_dx, dp_dy; its axis-aligned
/// bounds, in cells). In ±1 form the checker is the product s(x)·s(y)·s(z), so the box filter
/// is the product of the three filtered square waves, and the colour the mix of a and b by it.
template <class F>
HIKARI_INLINE HIKARI_HD Vec3T<F> texture_colour(const CheckerTexture& t,
                                                const SurfacePoint<F>& point) {
    static_assert(k_is_scalar<F>, "the checker has no lane form");
    const float inverse_size = 1.0f / t.size;
    const Vec3 q = (point.position + Vec3(t.offset)) * inverse_size;
    const auto width = [&](int a) {
        return (std::abs(point.dp_dx[a]) + std::abs(point.dp_dy[a])) * inverse_size;
    };
    const float even = filtered_square_wave(q.x, width(0)) * filtered_square_wave(q.y, width(1)) *
                       filtered_square_wave(q.z, width(2));
    const float a = 0.5f + 0.5f * even;
    return t.color_a * a + t.color_b * (1.0f - a);
}

}  // namespace hikari
