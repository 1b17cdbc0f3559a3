#pragma once
// The body of the Z-buffer tile kernel (raster/zbuffer_tile.h), written as plain loops over 8
// lanes that the compiler vectorises for the target of the file that includes this header. Only
// internal-linkage code lives here: each including file gets its own build of it.

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>

#if defined(HIKARI_ZBUFFER_AVX512) || defined(HIKARI_ZBUFFER_AVX2)
#include <immintrin.h>
#endif

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

/// The per-pixel loop of for_each_covered_pixel, for tiny triangles and the rare huge one.
void draw_per_pixel(const HalfSpaceTriangle& h, uint32_t id, TileDepth& target) {
    const Tile& tile = *target.tile;
    for_each_covered_pixel(h, tile.x0, tile.y0, tile.x1, tile.y1,
                           [&](int x, int y, float b0, float b1, float b2) {
                               const float z = interpolated_depth(h, b0, b1, b2);
                               const int i = (y - tile.y0) * k_tile_size + (x - tile.x0);
                               ++target.tested;
                               if (z < target.depth[i]) {
                                   target.depth[i] = z;
                                   if (target.nearest) target.nearest[i] = id;
                               }
                           });
}

/// What every lane version of draw_lanes needs: the triangle's bounds in the tile, the edge
/// functions at the first row's first lane group, their steps, and each lane's offset.
struct LaneSetup {
    int x0, x1, y0, y1;  ///< pixels of the triangle's bounds inside the tile
    int g0;              ///< the first lane group: the 8-pixel column of the tile that holds x0
    int64_t row[3], step_y[3], group_step[3];
    int64_t step_x[3];  ///< per pixel to the right; lane k is k steps from its group's start
    float inv_area;

    /// False when the triangle's bounds miss the tile.
    bool init(const HalfSpaceTriangle& h, const Tile& tile) {
        x0 = std::max(tile.x0, h.x0), x1 = std::min(tile.x1, h.x1);
        y0 = std::max(tile.y0, h.y0), y1 = std::min(tile.y1, h.y1);
        if (x0 >= x1 || y0 >= y1) return false;
        g0 = tile.x0 + (x0 - tile.x0) / k_lanes * k_lanes;
        const int64_t px = int64_t{g0} * k_subpixel_one + k_subpixel_one / 2;
        const int64_t py = int64_t{y0} * k_subpixel_one + k_subpixel_one / 2;
        for (int e = 0; e < 3; ++e) {
            const int a = (e + 1) % 3, b = (e + 2) % 3;
            const int64_t dx = h.x[b] - h.x[a], dy = h.y[b] - h.y[a];
            row[e] = dx * (py - h.y[a]) - dy * (px - h.x[a]) + h.bias[e];
            step_y[e] = dx * k_subpixel_one;
            step_x[e] = -dy * k_subpixel_one;
            group_step[e] = step_x[e] * k_lanes;
        }
        inv_area = 1.0f / static_cast<float>(h.area());
        return true;
    }

    /// Bit k set where pixel g + k lies in [x0, x1).
    unsigned column_bits(int g) const {
        const int lo = std::max(x0 - g, 0), hi = std::min(x1 - g, k_lanes);
        return ((1u << hi) - 1u) & ~((1u << lo) - 1u);
    }
};

#if defined(HIKARI_ZBUFFER_AVX512)
/// One triangle over the tile in rows of 8 pixels aligned to the tile, AVX-512: the 8 lanes'
/// edge functions in one register of int64, converted exactly (vcvtqq2ps rounds once, as
/// static_cast<float> does).
void draw_lanes(const HalfSpaceTriangle& h, uint32_t id, TileDepth& target) {
    const Tile& tile = *target.tile;
    LaneSetup s;
    if (!s.init(h, tile)) return;
    const __m512i lane = _mm512_setr_epi64(0, 1, 2, 3, 4, 5, 6, 7);
    const __m512i off0 = _mm512_mullo_epi64(_mm512_set1_epi64(s.step_x[0]), lane);
    const __m512i off1 = _mm512_mullo_epi64(_mm512_set1_epi64(s.step_x[1]), lane);
    const __m512i off2 = _mm512_mullo_epi64(_mm512_set1_epi64(s.step_x[2]), lane);
    const __m512i bias0 = _mm512_set1_epi64(h.bias[0]), bias1 = _mm512_set1_epi64(h.bias[1]),
                  bias2 = _mm512_set1_epi64(h.bias[2]);
    const __m256 inv_area = _mm256_set1_ps(s.inv_area);
    const __m256 iw0 = _mm256_set1_ps(h.inv_w[0]), iw1 = _mm256_set1_ps(h.inv_w[1]),
                 iw2 = _mm256_set1_ps(h.inv_w[2]);
    const __m256 one = _mm256_set1_ps(1.0f);
    const __m256i ids = _mm256_set1_epi32(static_cast<int>(id));
    for (int y = s.y0; y < s.y1; ++y) {
        int64_t base0 = s.row[0], base1 = s.row[1], base2 = s.row[2];
        for (int g = s.g0; g < s.x1; g += k_lanes) {
            const __m512i e0 = _mm512_add_epi64(_mm512_set1_epi64(base0), off0);
            const __m512i e1 = _mm512_add_epi64(_mm512_set1_epi64(base1), off1);
            const __m512i e2 = _mm512_add_epi64(_mm512_set1_epi64(base2), off2);
            base0 += s.group_step[0];
            base1 += s.group_step[1];
            base2 += s.group_step[2];
            const __m512i any_sign = _mm512_or_si512(_mm512_or_si512(e0, e1), e2);
            const __mmask8 inside = static_cast<__mmask8>(
                _mm512_cmpge_epi64_mask(any_sign, _mm512_setzero_si512()) & s.column_bits(g));
            if (!inside) continue;
            target.tested += static_cast<uint64_t>(std::popcount(static_cast<unsigned>(inside)));
            const __m256 b0 =
                _mm256_mul_ps(_mm512_cvtepi64_ps(_mm512_sub_epi64(e0, bias0)), inv_area);
            const __m256 b1 =
                _mm256_mul_ps(_mm512_cvtepi64_ps(_mm512_sub_epi64(e1, bias1)), inv_area);
            const __m256 b2 =
                _mm256_mul_ps(_mm512_cvtepi64_ps(_mm512_sub_epi64(e2, bias2)), inv_area);
            const __m256 inv_w =
                _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(b0, iw0), _mm256_mul_ps(b1, iw1)),
                              _mm256_mul_ps(b2, iw2));
            const __m256 z = _mm256_div_ps(one, inv_w);
            const int at = (y - tile.y0) * k_tile_size + (g - tile.x0);
            const __m256 stored = _mm256_loadu_ps(target.depth + at);
            // Alg 4.2's depth test.
            const __mmask8 won = _mm256_mask_cmp_ps_mask(inside, z, stored, _CMP_LT_OQ);
            _mm256_mask_storeu_ps(target.depth + at, won, z);
            if (target.nearest) _mm256_mask_storeu_epi32(target.nearest + at, won, ids);
        }
        s.row[0] += s.step_y[0];
        s.row[1] += s.step_y[1];
        s.row[2] += s.step_y[2];
    }
}
#elif defined(HIKARI_ZBUFFER_AVX2)
/// Four int64 lanes as doubles, exactly for |x| < 2^51 (exact_to_float's trick).
inline __m256d exact_to_double(__m256i x) {
    const __m256i magic_bits = _mm256_set1_epi64x(0x4338000000000000);
    return _mm256_sub_pd(_mm256_castsi256_pd(_mm256_add_epi64(x, magic_bits)),
                         _mm256_set1_pd(6755399441055744.0));
}

/// Eight int64 lanes (two registers) as floats, rounded once.
inline __m256 exact_to_float8(__m256i lo, __m256i hi) {
    return _mm256_set_m128(_mm256_cvtpd_ps(exact_to_double(hi)),
                           _mm256_cvtpd_ps(exact_to_double(lo)));
}

/// One triangle over the tile in rows of 8 pixels aligned to the tile, AVX2: the 8 lanes'
/// edge functions in two registers of int64 each.
void draw_lanes(const HalfSpaceTriangle& h, uint32_t id, TileDepth& target) {
    const Tile& tile = *target.tile;
    LaneSetup s;
    if (!s.init(h, tile)) return;
    __m256i off_lo[3], off_hi[3], bias[3];
    for (int e = 0; e < 3; ++e) {
        const int64_t step = s.step_x[e];
        off_lo[e] = _mm256_setr_epi64x(0, step, 2 * step, 3 * step);
        off_hi[e] = _mm256_add_epi64(off_lo[e], _mm256_set1_epi64x(4 * step));
        bias[e] = _mm256_set1_epi64x(h.bias[e]);
    }
    const __m256 inv_area = _mm256_set1_ps(s.inv_area);
    const __m256 iw0 = _mm256_set1_ps(h.inv_w[0]), iw1 = _mm256_set1_ps(h.inv_w[1]),
                 iw2 = _mm256_set1_ps(h.inv_w[2]);
    const __m256 one = _mm256_set1_ps(1.0f);
    const __m256i ids = _mm256_set1_epi32(static_cast<int>(id));
    const __m256i lane_bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
    const __m256i minus_one = _mm256_set1_epi64x(-1);
    for (int y = s.y0; y < s.y1; ++y) {
        int64_t base[3] = {s.row[0], s.row[1], s.row[2]};
        for (int g = s.g0; g < s.x1; g += k_lanes) {
            __m256i lo[3], hi[3];
            for (int e = 0; e < 3; ++e) {
                const __m256i b = _mm256_set1_epi64x(base[e]);
                lo[e] = _mm256_add_epi64(b, off_lo[e]);
                hi[e] = _mm256_add_epi64(b, off_hi[e]);
                base[e] += s.group_step[e];
            }
            const __m256i or_lo = _mm256_or_si256(_mm256_or_si256(lo[0], lo[1]), lo[2]);
            const __m256i or_hi = _mm256_or_si256(_mm256_or_si256(hi[0], hi[1]), hi[2]);
            const unsigned sign_bits =
                static_cast<unsigned>(
                    _mm256_movemask_pd(_mm256_castsi256_pd(_mm256_cmpgt_epi64(or_lo, minus_one)))) |
                static_cast<unsigned>(
                    _mm256_movemask_pd(_mm256_castsi256_pd(_mm256_cmpgt_epi64(or_hi, minus_one))))
                    << 4;
            const unsigned inside_bits = sign_bits & s.column_bits(g);
            if (!inside_bits) continue;
            target.tested += static_cast<uint64_t>(std::popcount(inside_bits));
            const __m256i inside = _mm256_cmpeq_epi32(
                _mm256_and_si256(_mm256_set1_epi32(static_cast<int>(inside_bits)), lane_bit),
                lane_bit);
            __m256 b[3];
            for (int e = 0; e < 3; ++e)
                b[e] = _mm256_mul_ps(exact_to_float8(_mm256_sub_epi64(lo[e], bias[e]),
                                                     _mm256_sub_epi64(hi[e], bias[e])),
                                     inv_area);
            const __m256 inv_w =
                _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(b[0], iw0), _mm256_mul_ps(b[1], iw1)),
                              _mm256_mul_ps(b[2], iw2));
            const __m256 z = _mm256_div_ps(one, inv_w);
            const int at = (y - tile.y0) * k_tile_size + (g - tile.x0);
            const __m256 stored = _mm256_loadu_ps(target.depth + at);
            // Alg 4.2's depth test.
            const __m256 won =
                _mm256_and_ps(_mm256_castsi256_ps(inside), _mm256_cmp_ps(z, stored, _CMP_LT_OQ));
            _mm256_storeu_ps(target.depth + at, _mm256_blendv_ps(stored, z, won));
            if (target.nearest) {
                __m256i* nearest = reinterpret_cast<__m256i*>(target.nearest + at);
                _mm256_storeu_si256(nearest, _mm256_castps_si256(_mm256_blendv_ps(
                                                 _mm256_castsi256_ps(_mm256_loadu_si256(nearest)),
                                                 _mm256_castsi256_ps(ids), won)));
            }
        }
        s.row[0] += s.step_y[0];
        s.row[1] += s.step_y[1];
        s.row[2] += s.step_y[2];
    }
}
#else
/// One triangle over the tile in rows of 8 pixels aligned to the tile, as plain loops over the
/// lanes. The arithmetic is for_each_covered_pixel's: exact edge functions in 1/256 pixel units,
/// weights (E − bias) / area in float, z = 1 / Σ b_i inv_w_i.
void draw_lanes(const HalfSpaceTriangle& h, uint32_t id, TileDepth& target) {
    const Tile& tile = *target.tile;
    LaneSetup s;
    if (!s.init(h, tile)) return;
    for (int y = s.y0; y < s.y1; ++y) {
        int64_t base[3] = {s.row[0], s.row[1], s.row[2]};
        for (int g = s.g0; g < s.x1; g += k_lanes) {
            const unsigned columns = s.column_bits(g);
            const int at = (y - tile.y0) * k_tile_size + (g - tile.x0);
            for (int k = 0; k < k_lanes; ++k) {
                const int64_t e0 = base[0] + s.step_x[0] * k;
                const int64_t e1 = base[1] + s.step_x[1] * k;
                const int64_t e2 = base[2] + s.step_x[2] * k;
                if ((e0 | e1 | e2) < 0 || !(columns >> k & 1u)) continue;
                ++target.tested;
                const float b0 = exact_to_float(e0 - h.bias[0]) * s.inv_area;
                const float b1 = exact_to_float(e1 - h.bias[1]) * s.inv_area;
                const float b2 = exact_to_float(e2 - h.bias[2]) * s.inv_area;
                const float z = interpolated_depth(h, b0, b1, b2);
                // Alg 4.2's depth test.
                if (z < target.depth[at + k]) {
                    target.depth[at + k] = z;
                    if (target.nearest) target.nearest[at + k] = id;
                }
            }
            for (int e = 0; e < 3; ++e) base[e] += s.group_step[e];
        }
        for (int e = 0; e < 3; ++e) s.row[e] += s.step_y[e];
    }
}
#endif

/// Pixel centres in the bounds below which a triangle takes the per-pixel loop: the lane setup
/// costs more than a few stepped evaluations.
constexpr int k_few_pixels = 4;

/// The largest depth of the tile's pixels.
float farthest_depth(const TileDepth& target) {
    const Tile& tile = *target.tile;
    float most = 0.0f;
    if (tile.x1 - tile.x0 == k_tile_size && tile.y1 - tile.y0 == k_tile_size) {
        // Column by column (no reduction across lanes until the end): vectorises.
        std::array<float, k_tile_size> column{};
        for (int y = 0; y < k_tile_size; ++y)
            for (int x = 0; x < k_tile_size; ++x) {
                const float d = target.depth[y * k_tile_size + x];
                column[x] = column[x] < d ? d : column[x];
            }
        for (const float d : column) most = std::max(most, d);
        return most;
    }
    for (int y = 0; y < tile.y1 - tile.y0; ++y)
        for (int x = 0; x < tile.x1 - tile.x0; ++x)
            most = std::max(most, target.depth[y * k_tile_size + x]);
    return most;
}

/// Triangles drawn between two refreshes of the tile's farthest depth.
constexpr size_t k_refresh_interval = 32;

void zbuffer_tile_body(const HalfSpaceTriangle* setup, const uint32_t* triangles, size_t count,
                       TileDepth& target) {
    size_t drawn = 0;
    constexpr size_t k_prefetch_ahead = 8;
    for (size_t k = 0; k < count; ++k) {
        // A tile's triangles lie far apart in the setup array: fetch a few ahead.
        if (k + k_prefetch_ahead < count) {
            const char* ahead =
                reinterpret_cast<const char*>(&setup[triangles[k + k_prefetch_ahead]]);
            __builtin_prefetch(ahead);  // one line: HalfSpaceTriangle is cache-line sized
        }
        const uint32_t t = triangles[k];
        const HalfSpaceTriangle& h = setup[t];
        // Hierarchical rejection: the whole tile is nearer than any point of the triangle.
        if (h.nearest_depth > target.farthest) continue;
        const int x0 = std::max(target.tile->x0, h.x0), x1 = std::min(target.tile->x1, h.x1);
        const int y0 = std::max(target.tile->y0, h.y0), y1 = std::min(target.tile->y1, h.y1);
        // A dense mesh's tiny triangles, and the rare huge one, take the per-pixel loop.
        if ((x1 - x0) * (y1 - y0) <= k_few_pixels || h.area() >= k_lane_area_limit)
            draw_per_pixel(h, t, target);
        else
            draw_lanes(h, t, target);
        // Depths only decrease, so a farthest depth not yet refreshed still bounds them all.
        if (++drawn % k_refresh_interval == 0) target.farthest = farthest_depth(target);
    }
}

}  // namespace
}  // namespace hikari::detail
