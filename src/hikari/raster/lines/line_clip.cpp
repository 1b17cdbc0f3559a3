#include "hikari/raster/lines/line_clip.h"

#include <algorithm>

namespace hikari {

std::optional<ClipInterval> clip_segment(Vec4 a, Vec4 b, float margin) {
    const float g = 1.0f + margin;
    // Signed distances to the five planes, ≥ 0 inside: near, then the four sides.
    const float da[5] = {a.z + a.w, g * a.w - a.x, g * a.w + a.x, g * a.w - a.y, g * a.w + a.y};
    const float db[5] = {b.z + b.w, g * b.w - b.x, g * b.w + b.x, g * b.w - b.y, g * b.w + b.y};
    ClipInterval r;
    for (int plane = 0; plane < 5; ++plane) {
        // The distance is affine in t, d(t) = da + t (db − da): the inside is a half-line of t.
        if (!(da[plane] >= 0.0f) && !(db[plane] >= 0.0f)) return std::nullopt;
        if (da[plane] >= 0.0f && db[plane] >= 0.0f) continue;
        const float t = da[plane] / (da[plane] - db[plane]);
        if (da[plane] < 0.0f)
            r.t0 = std::max(r.t0, t);
        else
            r.t1 = std::min(r.t1, t);
    }
    if (!(r.t0 < r.t1)) return std::nullopt;
    return r;
}

}  // namespace hikari
