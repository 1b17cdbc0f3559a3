#include "hikari/raster/half_space.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace hikari {

namespace {

/// std::llround without the library call: a float times 256 is exact in double, and so is that
/// plus or minus one half below 2^52, so truncating it rounds halves away from zero as llround.
int32_t round_half_away(double v) { return static_cast<int32_t>(v + std::copysign(0.5, v)); }

}  // namespace

bool setup_half_space(const ScreenTriangle& t, int width, int height, HalfSpaceTriangle& out) {
    // Far beyond the guard band (raster/clip.h), which keeps every vertex within a few
    // viewports of the image: snapped coordinates then stay below 2^30 (HalfSpaceTriangle).
    constexpr double k_limit = 1 << 21;
    std::array<int, 3> order{0, 1, 2};
    for (int i = 0; i < 3; ++i) {
        const Vec3 p = t.v[i].position;
        if (!(std::abs(p.x) < k_limit && std::abs(p.y) < k_limit)) return false;
        out.x[i] = round_half_away(static_cast<double>(p.x) * k_subpixel_one);
        out.y[i] = round_half_away(static_cast<double>(p.y) * k_subpixel_one);
    }
    // Pixels i with centre (i + 1/2) · 256 inside [min, max]: i from ⌈(min − 128) / 256⌉ to
    // ⌊(max − 128) / 256⌋ (arithmetic shifts floor). A triangle between pixel centres stops here.
    const auto [xmin, xmax] = std::minmax({out.x[0], out.x[1], out.x[2]});
    const auto [ymin, ymax] = std::minmax({out.y[0], out.y[1], out.y[2]});
    constexpr int64_t half = k_subpixel_one / 2;
    auto clamp_to = [](int64_t v, int limit) {
        return static_cast<int>(std::clamp<int64_t>(v, 0, limit));
    };
    out.x0 = clamp_to(-((half - xmin) >> k_subpixel_bits), width);
    out.x1 = clamp_to(((xmax - half) >> k_subpixel_bits) + 1, width);
    out.y0 = clamp_to(-((half - ymin) >> k_subpixel_bits), height);
    out.y1 = clamp_to(((ymax - half) >> k_subpixel_bits) + 1, height);
    if (out.x0 >= out.x1 || out.y0 >= out.y1) return false;
    int64_t area = out.area();
    if (area == 0) return false;
    if (area < 0) {  // make the area positive so that "inside" is E ≥ 0 on every edge
        std::swap(out.x[1], out.x[2]);
        std::swap(out.y[1], out.y[2]);
        std::swap(order[1], order[2]);
    }
    for (int i = 0; i < 3; ++i) {
        out.inv_w[i] = t.v[order[i]].inv_w;
        const int a = (i + 1) % 3, b = (i + 2) % 3;
        const int64_t dx = out.x[b] - out.x[a], dy = out.y[b] - out.y[a];
        // With y down and positive area, an edge going up (dy < 0) is a left edge, a horizontal
        // edge going right is a top edge.
        const bool top_left = dy < 0 || (dy == 0 && dx > 0);
        out.bias[i] = top_left ? 0 : -1;
    }
    // Interpolated 1/w lies between the corners' up to a few roundings of the weights, so the
    // largest corner value, rounded up by far more than those, bounds every pixel's depth.
    const auto [least_inv_w, most_inv_w] = std::minmax({out.inv_w[0], out.inv_w[1], out.inv_w[2]});
    out.nearest_depth = least_inv_w > 0.0f && std::isfinite(most_inv_w)
                            ? (1.0f / most_inv_w) * (1.0f - 1e-5f)
                            : -std::numeric_limits<float>::infinity();
    return true;
}

}  // namespace hikari
