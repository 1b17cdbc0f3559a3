#pragma once
// Starting secondary rays just off a surface, so they do not hit the surface they leave.

#include <bit>
#include <cmath>
#include <cstdint>

#include "hikari/core/vec.h"

namespace hikari {

/// `p` moved off the surface along the geometric normal `n` (pointing to the side the new ray
/// leaves from) by a few ulps of p's magnitude: Wächter & Binder, "A Fast and Robust Method for
/// Avoiding Self-Intersection" (Ray Tracing Gems, ch. 6). A fixed epsilon would be too large
/// for small models and too small far from the origin.
inline Vec3 offset_ray_origin(Vec3 p, Vec3 n) {
    constexpr float k_origin = 1.0f / 32.0f;
    constexpr float k_float_scale = 1.0f / 65536.0f;
    constexpr float k_int_scale = 256.0f;
    Vec3 out;
    for (int i = 0; i < 3; ++i) {
        const auto offset_ulps = static_cast<int32_t>(k_int_scale * n[i]);
        const auto bits = std::bit_cast<int32_t>(p[i]);
        const float moved = std::bit_cast<float>(bits + (p[i] < 0 ? -offset_ulps : offset_ulps));
        out[i] = std::abs(p[i]) < k_origin ? p[i] + k_float_scale * n[i] : moved;
    }
    return out;
}

}  // namespace hikari
