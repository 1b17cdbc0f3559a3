#pragma once
// Half-space (edge function) rasterization (Pineda 1988): a pixel centre is inside a triangle
// when it is on the inner side of all three edges. Vertices are snapped to 1/256 pixel and the
// edge functions evaluated exactly in 64-bit integers, so the top-left fill rule (as in Direct3D
// and OpenGL) gives every pixel centre on a shared edge to exactly one of the two triangles.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "hikari/core/host_device.h"
#include "hikari/raster/screen_triangle.h"

namespace hikari {

/// Fractional bits of the snapped vertex coordinates.
inline constexpr int k_subpixel_bits = 8;
inline constexpr int64_t k_subpixel_one = int64_t{1} << k_subpixel_bits;

/// A screen triangle ready for edge-function traversal. Vertices are reordered so that the
/// signed area is positive; edge i runs between the two vertices other than i. One cache line:
/// a tile reads the setup of each of its triangles, scattered in memory, so its size is the
/// rasterizer's memory traffic. Coordinates stay below 2^30 (setup_half_space refuses others),
/// so differences of two fit in 32 bits and products of two differences in 63.
struct alignas(64) HalfSpaceTriangle {
    std::array<int32_t, 3> x, y;  ///< snapped vertex positions, in 1/256 pixel
    std::array<float, 3> inv_w;   ///< 1 / w of each (reordered) vertex
    /// A lower bound of the depth 1 / inv_w at every covered pixel (−infinity when unknown): a
    /// Z-buffer whose tile is nearer everywhere can skip the triangle (hierarchical rejection).
    float nearest_depth = 0;
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< pixels whose centres the bounding box holds,
                                         ///< [x0, x1) × [y0, y1), clipped to the viewport
    std::array<int8_t, 3> bias;  ///< 0 for top-left edges (a centre on them is in), −1 else

    /// Twice the signed area, in 1/256² pixel², > 0.
    HIKARI_HD int64_t area() const {
        return int64_t{x[1] - x[0]} * (y[2] - y[0]) - int64_t{y[1] - y[0]} * (x[2] - x[0]);
    }
};

/// The view depth at a point of `h` with screen-space weights (b0, b1, b2): 1/w is affine in
/// screen space, so it is interpolated and inverted (Alg 4.2's z). Every scalar path of the
/// Z-buffer rounds through this one expression, so the SIMD kernels can match it exactly.
HIKARI_HD inline float interpolated_depth(const HalfSpaceTriangle& h, float b0, float b1,
                                          float b2) {
    return 1.0f / (b0 * h.inv_w[0] + b1 * h.inv_w[1] + b2 * h.inv_w[2]);
}

/// Prepares `t` for rasterization in a width × height viewport. Returns false when the triangle
/// covers no pixel centre for sure: zero area, off screen, or coordinates that are not finite
/// or beyond the guard band's range.
/// (Inline: it runs once per triangle and frame, from the Z-buffer's setup loop.)
/// std::llround without the library call: a float times 256 is exact in double, and so is that
/// plus or minus one half below 2^52, so truncating it rounds halves away from zero as llround.
HIKARI_HD inline int32_t round_half_away(double v) {
    return static_cast<int32_t>(v + std::copysign(0.5, v));
}

HIKARI_HD inline bool setup_half_space(const ScreenTriangle& t, int width, int height,
                                       HalfSpaceTriangle& out) {
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

/// Calls `fn(x, y, b0, b1, b2)` for every pixel (x, y) of [x0, x1) × [y0, y1) whose centre the
/// triangle covers under the top-left rule, with the screen-space barycentric weights of the
/// (reordered) vertices. The edge functions step incrementally: one add per edge and pixel.
template <class Fn>
void for_each_covered_pixel(const HalfSpaceTriangle& t, int x0, int y0, int x1, int y1, Fn&& fn) {
    x0 = std::max(x0, t.x0);
    y0 = std::max(y0, t.y0);
    x1 = std::min(x1, t.x1);
    y1 = std::min(y1, t.y1);
    if (x0 >= x1 || y0 >= y1) return;
    const int64_t px = int64_t{x0} * k_subpixel_one + k_subpixel_one / 2;
    const int64_t py = int64_t{y0} * k_subpixel_one + k_subpixel_one / 2;
    std::array<int64_t, 3> row, step_x, step_y;
    for (int e = 0; e < 3; ++e) {
        const int a = (e + 1) % 3, b = (e + 2) % 3;
        const int64_t dx = t.x[b] - t.x[a], dy = t.y[b] - t.y[a];
        // E(p) = dx (p.y − a.y) − dy (p.x − a.x), positive inside.
        row[e] = dx * (py - t.y[a]) - dy * (px - t.x[a]) + t.bias[e];
        step_x[e] = -dy * k_subpixel_one;
        step_y[e] = dx * k_subpixel_one;
    }
    const float inv_area = 1.0f / static_cast<float>(t.area());
    for (int y = y0; y < y1; ++y) {
        std::array<int64_t, 3> e = row;
        for (int x = x0; x < x1; ++x) {
            if ((e[0] | e[1] | e[2]) >= 0)
                fn(x, y, static_cast<float>(e[0] - t.bias[0]) * inv_area,
                   static_cast<float>(e[1] - t.bias[1]) * inv_area,
                   static_cast<float>(e[2] - t.bias[2]) * inv_area);
            for (int k = 0; k < 3; ++k) e[k] += step_x[k];
        }
        for (int k = 0; k < 3; ++k) row[k] += step_y[k];
    }
}

}  // namespace hikari
