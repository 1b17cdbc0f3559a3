#include "hikari/frame/aov_picture.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include "hikari/core/color.h"
#include "hikari/core/ray.h"

namespace hikari {

namespace {

/// A saturated colour of hue `h` in [0, 1) (HSV with s = 0.7, v = 0.95).
Vec3 hue_colour(float h) {
    constexpr float s = 0.7f, v = 0.95f;
    const float sector = h * 6.0f;
    const int i = static_cast<int>(sector) % 6;
    const float f = sector - std::floor(sector);
    const float p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    switch (i) {
        case 0:
            return {v, t, p};
        case 1:
            return {q, v, p};
        case 2:
            return {p, v, t};
        case 3:
            return {p, q, v};
        case 4:
            return {t, p, v};
        default:
            return {v, p, q};
    }
}

}  // namespace

Vec3 ramp_colour(float t) {
    constexpr Vec3 k_stops[] = {{0.05f, 0.05f, 0.35f}, {0.1f, 0.5f, 0.9f},  {0.2f, 0.8f, 0.3f},
                                {0.95f, 0.85f, 0.2f},  {0.9f, 0.25f, 0.1f}, {1.0f, 1.0f, 1.0f}};
    constexpr int k_last = static_cast<int>(std::size(k_stops)) - 1;
    const float x = std::clamp(t, 0.0f, 1.0f) * k_last;
    const int i = std::min(static_cast<int>(x), k_last - 1);
    const float f = x - static_cast<float>(i);
    return k_stops[i] * (1.0f - f) + k_stops[i + 1] * f;
}

Vec3 index_colour(uint32_t i) {
    // The golden ratio's fractional part spreads consecutive indices over the hues.
    return hue_colour(static_cast<float>(std::fmod(0.618033988749895 * i, 1.0)));
}

std::optional<DepthRange> visible_depth_range(const Framebuffer& fb,
                                              std::span<const PrimitiveId> unbounded) {
    const bool have_ids = fb.id.size() == fb.depth.size();
    float lo = k_infinity, hi = -k_infinity, hi_bounded = -k_infinity;
    for (size_t i = 0; i < fb.depth.size(); ++i) {
        const float d = fb.depth[i];
        if (!std::isfinite(d)) continue;
        lo = std::min(lo, d), hi = std::max(hi, d);
        // The id buffer holds 1 + the primitive id.
        if (!have_ids || std::ranges::find(unbounded, fb.id[i] - 1) == unbounded.end())
            hi_bounded = std::max(hi_bounded, d);
    }
    if (!(lo <= hi)) return std::nullopt;
    return DepthRange{lo, lo <= hi_bounded ? hi_bounded : hi};
}

std::vector<PrimitiveId> unbounded_primitives(const Scene& scene) {
    std::vector<PrimitiveId> ids;
    for (const Plane& plane : scene.planes) ids.push_back(plane.id);
    return ids;
}

Image aov_picture(const Framebuffer& fb, Aov aov, std::optional<DepthRange> range,
                  std::span<const PrimitiveId> unbounded) {
    const size_t pixels = static_cast<size_t>(fb.width()) * static_cast<size_t>(fb.height());
    if (fb.depth.size() != pixels)
        throw std::invalid_argument("aov_picture: the render kept colour only");
    if (!range) range = visible_depth_range(fb, unbounded);
    Image out(fb.width(), fb.height());
    for (size_t i = 0; i < pixels; ++i) {
        Vec3 v(0.0f);
        switch (aov) {
            case Aov::depth:
                if (std::isfinite(fb.depth[i]) && range) {
                    const float span = range->far - range->near;
                    // A single depth (a flat view of one plane) is all "near": white.
                    const float t = span > 0.0f ? (fb.depth[i] - range->near) / span : 0.0f;
                    v = Vec3(1.0f - std::clamp(t, 0.0f, 1.0f));
                }
                break;
            case Aov::id:
                if (fb.id[i] != k_background_id) v = index_colour(fb.id[i] - 1);
                break;
            case Aov::normal:
                if (fb.normal[i] != Vec3(0.0f)) v = Vec3(0.5f) + 0.5f * fb.normal[i];
                break;
            default:
                throw std::invalid_argument("aov_picture: not a buffer");
        }
        out.pixels[i] = decode_srgb(v);
    }
    return out;
}

}  // namespace hikari
