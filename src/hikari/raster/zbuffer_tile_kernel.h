#pragma once
// The body of the Z-buffer tile kernel (raster/zbuffer_tile.h), written as plain loops over 8
// lanes that the compiler vectorises for the target of the file that includes this header. Only
// internal-linkage code lives here: each including file gets its own build of it.

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>

#include "hikari/raster/zbuffer_tile.h"

namespace hikari::detail {
namespace {

constexpr int k_lanes = 8;

/// Exact int64 → float for |x| < 2^51, through double: x lands exactly in the mantissa of
/// 1.5 · 2^52 + x, and the one rounding to float is the one static_cast<float>(x) makes.
/// Unlike the int64 conversion, it vectorises without AVX-512.
inline float exact_to_float(int64_t x) {
    constexpr int64_t k_magic_bits = 0x4338000000000000;  // 1.5 · 2^52
    const double shifted = std::bit_cast<double>(x + k_magic_bits);
    return static_cast<float>(shifted - 6755399441055744.0);
}

/// Triangles whose edge values may reach 2^51 take the per-pixel loop.
constexpr int64_t k_lane_area_limit = int64_t{1} << 50;

/// The per-pixel loop of for_each_covered_pixel, for the rare huge triangle.
void draw_per_pixel(const HalfSpaceTriangle& h, uint32_t id, TileDepth& target) {
    const Tile& tile = *target.tile;
    for_each_covered_pixel(
        h, tile.x0, tile.y0, tile.x1, tile.y1, [&](int x, int y, float b0, float b1, float b2) {
            const float z = 1.0f / (b0 * h.inv_w[0] + b1 * h.inv_w[1] + b2 * h.inv_w[2]);
            const int i = (y - tile.y0) * k_tile_size + (x - tile.x0);
            if (z < target.depth[i]) {
                target.depth[i] = z;
                if (target.nearest) target.nearest[i] = id;
            }
        });
}

/// One triangle over the tile in rows of 8 pixels aligned to the tile. The arithmetic is
/// for_each_covered_pixel's: exact edge functions E(p) = dx (p.y − a.y) − dy (p.x − a.x) + bias
/// in 1/256 pixel units, weights (E − bias) / area in float, z = 1 / Σ b_i inv_w_i.
void draw_lanes(const HalfSpaceTriangle& h, uint32_t id, TileDepth& target) {
    const Tile& tile = *target.tile;
    const int x0 = std::max(tile.x0, h.x0), x1 = std::min(tile.x1, h.x1);
    const int y0 = std::max(tile.y0, h.y0), y1 = std::min(tile.y1, h.y1);
    if (x0 >= x1 || y0 >= y1) return;
    // The first lane group: the 8-pixel column of the tile that holds x0.
    const int g0 = tile.x0 + (x0 - tile.x0) / k_lanes * k_lanes;
    const int64_t px = int64_t{g0} * k_subpixel_one + k_subpixel_one / 2;
    const int64_t py = int64_t{y0} * k_subpixel_one + k_subpixel_one / 2;
    int64_t row[3], step_y[3], group_step[3];
    alignas(64) int64_t lane_offset[3][k_lanes];
    for (int e = 0; e < 3; ++e) {
        const int a = (e + 1) % 3, b = (e + 2) % 3;
        const int64_t dx = h.x[b] - h.x[a], dy = h.y[b] - h.y[a];
        row[e] = dx * (py - h.y[a]) - dy * (px - h.x[a]) + h.bias[e];
        step_y[e] = dx * k_subpixel_one;
        group_step[e] = -dy * k_subpixel_one * k_lanes;
        for (int k = 0; k < k_lanes; ++k) lane_offset[e][k] = -dy * k_subpixel_one * k;
    }
    const float inv_area = 1.0f / static_cast<float>(h.area);
    const float iw0 = h.inv_w[0], iw1 = h.inv_w[1], iw2 = h.inv_w[2];
    const int64_t bias0 = h.bias[0], bias1 = h.bias[1], bias2 = h.bias[2];
    for (int y = y0; y < y1; ++y) {
        int64_t base0 = row[0], base1 = row[1], base2 = row[2];
        for (int g = g0; g < x1; g += k_lanes) {
            alignas(64) int64_t e0[k_lanes], e1[k_lanes], e2[k_lanes];
            alignas(32) int32_t inside[k_lanes];
            int32_t any = 0;
            for (int k = 0; k < k_lanes; ++k) {
                e0[k] = base0 + lane_offset[0][k];
                e1[k] = base1 + lane_offset[1][k];
                e2[k] = base2 + lane_offset[2][k];
                const int x = g + k;
                inside[k] = ((e0[k] | e1[k] | e2[k]) >= 0) & (x >= x0) & (x < x1) ? -1 : 0;
                any |= inside[k];
            }
            base0 += group_step[0];
            base1 += group_step[1];
            base2 += group_step[2];
            if (!any) continue;
            const int at = (y - tile.y0) * k_tile_size + (g - tile.x0);
            float* depth = target.depth + at;
            alignas(32) float z[k_lanes];
            alignas(32) int32_t won[k_lanes];
            for (int k = 0; k < k_lanes; ++k) {
                const float b0 = exact_to_float(e0[k] - bias0) * inv_area;
                const float b1 = exact_to_float(e1[k] - bias1) * inv_area;
                const float b2 = exact_to_float(e2[k] - bias2) * inv_area;
                z[k] = 1.0f / (b0 * iw0 + b1 * iw1 + b2 * iw2);
                // Alg 4.2's depth test; lanes past the tile's row end are never inside.
                won[k] = inside[k] & (z[k] < depth[k] ? -1 : 0);
                depth[k] = won[k] ? z[k] : depth[k];
            }
            if (target.nearest) {
                uint32_t* nearest = target.nearest + at;
                for (int k = 0; k < k_lanes; ++k) nearest[k] = won[k] ? id : nearest[k];
            }
        }
        row[0] += step_y[0];
        row[1] += step_y[1];
        row[2] += step_y[2];
    }
}

/// The largest depth of the tile's pixels.
float farthest_depth(const TileDepth& target) {
    const Tile& tile = *target.tile;
    float most = 0.0f;
    for (int y = 0; y < tile.y1 - tile.y0; ++y)
        for (int x = 0; x < tile.x1 - tile.x0; ++x)
            most = std::max(most, target.depth[y * k_tile_size + x]);
    return most;
}

/// Triangles drawn between two refreshes of the tile's farthest depth.
constexpr size_t k_refresh_interval = 16;

void zbuffer_tile_body(const HalfSpaceTriangle* setup, const uint32_t* triangles, size_t count,
                       TileDepth& target) {
    size_t drawn = 0;
    for (size_t k = 0; k < count; ++k) {
        const uint32_t t = triangles[k];
        const HalfSpaceTriangle& h = setup[t];
        // Hierarchical rejection: the whole tile is nearer than any point of the triangle.
        if (h.nearest_depth > target.farthest) continue;
        if (h.area < k_lane_area_limit)
            draw_lanes(h, t, target);
        else
            draw_per_pixel(h, t, target);
        if (++drawn % k_refresh_interval == 0) target.farthest = farthest_depth(target);
    }
    target.farthest = farthest_depth(target);
}

}  // namespace
}  // namespace hikari::detail
