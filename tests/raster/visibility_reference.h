#pragma once
// Test support for the hidden-surface methods: an independent ray caster (per pixel centre, the
// covering triangle of smallest depth, by exact edge functions) and hand-built screen-space scenes,
// among them the lecture's failure cases of the depth sort (Fig 4.9a cyclic overlap, 4.9b
// piercing).

#include <cmath>
#include <cstdint>
#include <vector>

#include "hikari/core/rng.h"
#include "hikari/raster/screen_triangle.h"

namespace hikari::testing {

inline ScreenTriangle make_triangle(Vec3 a, Vec3 b, Vec3 c, uint32_t source = 0) {
    ScreenTriangle t;
    t.v[0].position = a;
    t.v[1].position = b;
    t.v[2].position = c;
    t.source = source;
    return t;
}

/// Ray casting at pixel centres: a centre is inside a triangle when every edge function is
/// positive, or zero on a top or left edge (the top-left rule); the nearest (smallest z) triangle
/// wins, ties going to the smaller index. Edge functions of float inputs are exact in double.
inline VisibilityBuffer ray_cast_visibility(const std::vector<ScreenTriangle>& triangles, int width,
                                            int height) {
    VisibilityBuffer out{width, height,
                         std::vector<uint32_t>(static_cast<size_t>(width) * height, k_no_triangle)};
    std::vector<double> depth(out.triangle.size(), INFINITY);
    for (uint32_t t = 0; t < triangles.size(); ++t) {
        double x[3], y[3], z[3];
        for (int k = 0; k < 3; ++k) {
            x[k] = triangles[t].v[k].position.x;
            y[k] = triangles[t].v[k].position.y;
            z[k] = triangles[t].v[k].position.z;
        }
        double area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
        if (area == 0 || !std::isfinite(area)) continue;
        if (area < 0) {  // make the interior the positive side of every edge
            std::swap(x[1], x[2]), std::swap(y[1], y[2]), std::swap(z[1], z[2]);
            area = -area;
        }
        for (int j = 0; j < height; ++j) {
            for (int i = 0; i < width; ++i) {
                const double px = i + 0.5, py = j + 0.5;
                double w[3];
                bool inside = true;
                for (int k = 0; k < 3 && inside; ++k) {
                    const int a = (k + 1) % 3, b = (k + 2) % 3;  // edge opposite vertex k
                    const double dx = x[b] - x[a], dy = y[b] - y[a];
                    w[k] = dx * (py - y[a]) - dy * (px - x[a]);
                    // in y-down screen space: a left edge runs upward, a top edge runs rightward
                    const bool top_left = dy < 0 || (dy == 0 && dx > 0);
                    inside = w[k] > 0 || (w[k] == 0 && top_left);
                }
                if (!inside) continue;
                const double d = (w[0] * z[0] + w[1] * z[1] + w[2] * z[2]) / area;
                const size_t p = static_cast<size_t>(j) * width + i;
                if (d < depth[p]) {
                    depth[p] = d;
                    out.triangle[p] = t;
                }
            }
        }
    }
    return out;
}

/// Pixels where two visibility buffers differ.
inline int64_t mismatches(const VisibilityBuffer& a, const VisibilityBuffer& b) {
    int64_t n = 0;
    for (size_t p = 0; p < a.triangle.size(); ++p) n += a.triangle[p] != b.triangle[p];
    return n;
}

/// `count` random triangles around a 256 × 256 image (some partly off it), each vertex at its own
/// random depth, so that many of them interpenetrate.
inline std::vector<ScreenTriangle> random_triangles(uint64_t seed, int count, float size) {
    Pcg32 rng(seed, 7);
    std::vector<ScreenTriangle> out;
    for (int t = 0; t < count; ++t) {
        const float cx = -20 + 296 * rng.next_float(), cy = -20 + 296 * rng.next_float();
        Vec3 v[3];
        for (Vec3& p : v)
            p = {cx + size * (2 * rng.next_float() - 1), cy + size * (2 * rng.next_float() - 1),
                 0.05f + 0.9f * rng.next_float()};
        out.push_back(make_triangle(v[0], v[1], v[2], static_cast<uint32_t>(t)));
    }
    return out;
}

/// A bar (two triangles) from `from` to `to`, `half_width` pixels either side, its depth going
/// linearly from z_from to z_to.
inline void add_bar(std::vector<ScreenTriangle>& out, Vec2 from, Vec2 to, float half_width,
                    float z_from, float z_to) {
    const float dx = to.x - from.x, dy = to.y - from.y;
    const float len = std::sqrt(dx * dx + dy * dy);
    const float nx = -dy / len * half_width, ny = dx / len * half_width;
    const Vec3 a{from.x + nx, from.y + ny, z_from}, b{from.x - nx, from.y - ny, z_from};
    const Vec3 c{to.x - nx, to.y - ny, z_to}, d{to.x + nx, to.y + ny, z_to};
    const auto source = static_cast<uint32_t>(out.size());
    out.push_back(make_triangle(a, b, c, source));
    out.push_back(make_triangle(a, c, d, source + 1));
}

/// Fig 4.9a (三すくみ): three bars along the sides of a triangle, each rising in depth from its
/// start corner to its end corner, so each is in front of the next at one crossing and behind the
/// previous one at another. No order of whole polygons paints this right.
inline std::vector<ScreenTriangle> three_bars() {
    const Vec2 corner[3] = {{128, 28}, {232, 210}, {24, 210}};
    std::vector<ScreenTriangle> out;
    for (int i = 0; i < 3; ++i) {
        const Vec2 s = corner[i], e = corner[(i + 1) % 3];
        const float dx = e.x - s.x, dy = e.y - s.y, len = std::sqrt(dx * dx + dy * dy);
        const float ext = 24 / len;  // reach past the corners so the crossings are whole squares
        add_bar(out, {s.x - ext * dx, s.y - ext * dy}, {e.x + ext * dx, e.y + ext * dy}, 16, 0.2f,
                0.8f);
    }
    return out;
}

/// Fig 4.9b (貫通): two triangles piercing each other along a slanted line; left of it the first is
/// nearer, right of it the second.
inline std::vector<ScreenTriangle> piercing_pair() {
    return {make_triangle({30, 40, 0.2f}, {230, 40, 0.8f}, {130, 235, 0.5f}, 0),
            make_triangle({20, 70, 0.85f}, {240, 60, 0.25f}, {120, 225, 0.45f}, 1)};
}

}  // namespace hikari::testing
