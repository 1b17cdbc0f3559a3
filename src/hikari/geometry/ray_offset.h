#pragma once
// Starting secondary rays just off a surface, so they do not hit the surface they leave.

#include <cstdint>

#include "hikari/core/lanes.h"
#include "hikari/core/vec.h"

namespace hikari {

/// `p` moved off the surface along the geometric normal `n` (pointing to the side the new ray
/// leaves from) by a few ulps of p's magnitude: Wächter & Binder, "A Fast and Robust Method for
/// Avoiding Self-Intersection" (Ray Tracing Gems, ch. 6). A fixed epsilon would be too large
/// for small models and too small far from the origin. Generic over the number type.
template <class F>
HIKARI_INLINE HIKARI_HD F offset_ray_coordinate(F p, F n) {
    constexpr float k_origin = 1.0f / 32.0f;
    constexpr float k_float_scale = 1.0f / 65536.0f;
    constexpr float k_int_scale = 256.0f;
    const IntOf<F> offset_ulps = truncate_to_int(F(k_int_scale) * n);
    const IntOf<F> bits = float_bits(p);
    const F moved = bits_float(bits + select(p < F(0.0f), IntOf<F>(0) - offset_ulps, offset_ulps));
    return select(abs_of(p) < F(k_origin), p + F(k_float_scale) * n, moved);
}

template <class F>
HIKARI_INLINE HIKARI_HD Vec3T<F> offset_ray_origin(const Vec3T<F>& p, const Vec3T<F>& n) {
    return {offset_ray_coordinate(p.x, n.x), offset_ray_coordinate(p.y, n.y),
            offset_ray_coordinate(p.z, n.z)};
}

}  // namespace hikari
