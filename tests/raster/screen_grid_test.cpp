#include "hikari/raster/screen_grid.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

namespace hikari {
namespace {

ScreenTriangle triangle(float x0, float y0, float x1, float y1, float x2, float y2) {
    ScreenTriangle t;
    t.v[0].position = Vec3(x0, y0, -0.5f);
    t.v[1].position = Vec3(x1, y1, -0.5f);
    t.v[2].position = Vec3(x2, y2, -0.5f);
    return t;
}

/// Whether segment (a, b) meets the box [lo, hi] (sampled finely: a reference, not a clipper).
bool segment_meets_box(Vec2 a, Vec2 b, Vec2 lo, Vec2 hi) {
    for (int k = 0; k <= 2000; ++k) {
        const float t = float(k) / 2000.0f;
        const float x = a.x + (b.x - a.x) * t, y = a.y + (b.y - a.y) * t;
        if (x >= lo.x && x <= hi.x && y >= lo.y && y <= hi.y) return true;
    }
    return false;
}

/// Every triangle whose box segment (a, b) crosses is found, over an image of `scale` × (100 ×
/// 80) pixels in cells of `cell` pixels.
void expect_segments_find_their_triangles(float scale, float cell) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-20.0f, 120.0f);  // some beyond the 100 × 80 image
    std::vector<ScreenTriangle> tris;
    for (int k = 0; k < 300; ++k) {
        const float x = u(rng), y = u(rng);
        tris.push_back(triangle(x * scale, y * scale, (x + u(rng) / 12) * scale, (y + 3) * scale,
                                (x - 2) * scale, (y + u(rng) / 15) * scale));
    }
    const ScreenGrid grid(tris, std::max(1, int(100 * scale)), std::max(1, int(80 * scale)), cell);
    for (int k = 0; k < 50; ++k) {
        const Vec2 a{u(rng) * scale, u(rng) * scale}, b{u(rng) * scale, u(rng) * scale};
        std::set<uint32_t> found;
        grid.for_each_along(a, b, 1.0f, [&](uint32_t i) { found.insert(i); });
        for (uint32_t i = 0; i < tris.size(); ++i) {
            Vec2 lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
            for (const ScreenVertex& v : tris[i].v) {
                lo = {std::min(lo.x, v.position.x), std::min(lo.y, v.position.y)};
                hi = {std::max(hi.x, v.position.x), std::max(hi.y, v.position.y)};
            }
            if (segment_meets_box(a, b, lo, hi)) EXPECT_TRUE(found.count(i)) << k << ", " << i;
        }
    }
}

TEST(ScreenGrid, FindsEveryTriangleWhoseBoxASegmentCrosses) {
    expect_segments_find_their_triangles(1.0f, 8.0f);
}

TEST(ScreenGrid, CellsOfAFractionOfAPixelServeATinyImage) {
    // The hidden-line grid of a 1 × 1 image (raster/lines/hidden_line.cpp): cells of 1/64 pixel.
    expect_segments_find_their_triangles(0.01f, 1.0f / 64.0f);
}

TEST(ScreenGrid, ADomainGridFindsTheSameTrianglesAtAnyScale) {
    // A grid over a box of the image plane in about n cells: scaling the scene scales the cells,
    // so a segment meets the same triangles at 1/1024 of the size (a power of two: the
    // scaled floats are exact).
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(0.0f, 100.0f);
    std::vector<ScreenTriangle> tris;
    std::vector<Vec2> segment_ends;
    for (int k = 0; k < 400; ++k) {
        const float x = u(rng), y = u(rng);
        tris.push_back(triangle(x, y, x + u(rng) / 20, y + 2, x - 1, y + u(rng) / 25));
    }
    for (int k = 0; k < 100; ++k) segment_ends.push_back({u(rng), u(rng)});
    auto scaled = [](std::vector<ScreenTriangle> t, float s) {
        for (ScreenTriangle& x : t)
            for (ScreenVertex& v : x.v)
                v.position = Vec3(v.position.x * s, v.position.y * s, -0.5f);
        return t;
    };
    std::vector<std::set<uint32_t>> found[2];
    for (int pass = 0; pass < 2; ++pass) {
        const float s = pass == 0 ? 1.0f : 1.0f / 1024.0f;
        auto at = [&](Vec2 v) { return Vec2{v.x * s, v.y * s}; };
        const std::vector<ScreenTriangle> t = scaled(tris, s);
        const ScreenGrid grid(t, {-5.0f * s, -5.0f * s}, {105.0f * s, 105.0f * s}, 400, 0.0f);
        EXPECT_GT(grid.cell_size(), 4.0f * s);
        for (size_t k = 0; k + 1 < segment_ends.size(); k += 2) {
            std::set<uint32_t> f;
            grid.for_each_along(at(segment_ends[k]), at(segment_ends[k + 1]), 0.01f * s,
                                [&](uint32_t i) { f.insert(i); });
            // every triangle whose box the segment crosses is among them
            for (uint32_t i = 0; i < t.size(); ++i) {
                Vec2 lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
                for (const ScreenVertex& v : t[i].v) {
                    lo = {std::min(lo.x, v.position.x), std::min(lo.y, v.position.y)};
                    hi = {std::max(hi.x, v.position.x), std::max(hi.y, v.position.y)};
                }
                if (segment_meets_box(at(segment_ends[k]), at(segment_ends[k + 1]), lo, hi))
                    EXPECT_TRUE(f.count(i)) << k << ", " << i;
            }
            found[pass].push_back(f);
        }
    }
    EXPECT_EQ(found[0], found[1]);
}

TEST(ScreenGrid, BoxQueryVisitsTheTrianglesInItsCells) {
    const std::vector<ScreenTriangle> tris = {triangle(1, 1, 5, 1, 1, 5),
                                              triangle(50, 50, 60, 50, 50, 60)};
    const ScreenGrid grid(tris, 64, 64, 8);
    std::set<uint32_t> found;
    grid.for_each_in_box({0, 0}, {7, 7}, [&](uint32_t i) { found.insert(i); });
    EXPECT_EQ(found, (std::set<uint32_t>{0}));
    found.clear();
    grid.for_each_in_box({-100, -100}, {200, 200}, [&](uint32_t i) { found.insert(i); });
    EXPECT_EQ(found, (std::set<uint32_t>{0, 1}));
}

}  // namespace
}  // namespace hikari
