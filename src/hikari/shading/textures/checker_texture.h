#pragma once
// The solid checker (POV-Ray's `checker` pattern) at a surface point.

#include "hikari/core/lanes.h"
#include "hikari/scene/texture.h"
#include "hikari/shading/surface.h"
#include "hikari/shading/textures/lane_form.h"

namespace hikari {

/// The parity of floor(v): 1 where odd. Floats of 2^31 or more in magnitude are multiples of
/// 256, so even; below that floor is truncation stepped down for negative non-integers.
template <class F>
HIKARI_INLINE IntOf<F> floor_parity(F v) {
    const F w = select(abs_of(v) < F(2147483648.0f), v, F(0.0f));
    const IntOf<F> truncated = truncate_to_int(w);
    const IntOf<F> floor = truncated - select(w < to_float(truncated), IntOf<F>(1), IntOf<F>(0));
    return floor & IntOf<F>(1);
}

/// Lanes compute the checker themselves.
template <>
inline constexpr bool k_texture_has_lane_form<CheckerTexture> = true;

/// The checker's colour at `point`: colour_a where the cells' floor sum is even, else colour_b.
template <class F>
HIKARI_INLINE Vec3T<F> texture_colour(const CheckerTexture& t, const SurfacePoint<F>& point) {
    const F inverse_size = F(1.0f / t.size);
    const Vec3T<F> q = (point.position + Vec3T<F>(t.offset)) * inverse_size;
    const MaskOf<F> odd =
        (floor_parity(q.x) ^ floor_parity(q.y) ^ floor_parity(q.z)) != IntOf<F>(0);
    return {select(odd, F(t.color_b.x), F(t.color_a.x)),
            select(odd, F(t.color_b.y), F(t.color_a.y)),
            select(odd, F(t.color_b.z), F(t.color_a.z))};
}

}  // namespace hikari
