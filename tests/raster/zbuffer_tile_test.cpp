#include "hikari/raster/zbuffer_tile.h"

#include <tbb/global_control.h>

#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "hikari/raster/zbuffer.h"

namespace hikari {
namespace {

/// Random screen triangles over a w × h image: small and large, partly off screen, some far
/// beyond it (huge edge values), some repeated at the same depth (ties).
std::vector<ScreenTriangle> random_triangles(int w, int h, size_t count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<ScreenTriangle> out;
    while (out.size() < count) {
        const float size = out.size() % 7 == 0 ? 3000.0f : (out.size() % 3 == 0 ? 60.0f : 6.0f);
        const float cx = unit(rng) * w, cy = unit(rng) * h;
        ScreenTriangle t;
        for (ScreenVertex& v : t.v) {
            v.inv_w = 0.2f + unit(rng);
            v.position = {cx + (unit(rng) - 0.5f) * size, cy + (unit(rng) - 0.5f) * size, 0.0f};
        }
        t.source = static_cast<uint32_t>(out.size());
        out.push_back(t);
        if (out.size() % 11 == 0) out.push_back(t);  // an exact tie: the first must stay
    }
    return out;
}

TEST(ZBufferTile, EveryInstructionSetGivesThePerPixelLoopsBuffer) {
    const int w = 203, h = 131;  // not a multiple of the tile size
    const auto triangles = random_triangles(w, h, 3000, 7);
    // The per-pixel loop (the observer's path) is the reference.
    std::vector<uint32_t> fragments;
    const VisibilityBuffer reference = zbuffer_visibility_counted(triangles, w, h, fragments);
    size_t covered = 0;
    for (const uint32_t t : reference.triangle) covered += t != k_no_triangle;
    ASSERT_GT(covered, static_cast<size_t>(w * h / 2));
    for (const SimdLevel level : supported_simd_levels()) {
        ZBufferWorkspace ws;
        std::vector<uint32_t> nearest(static_cast<size_t>(w) * h);
        std::vector<float> depth(nearest.size());
        zbuffer_draw(triangles, w, h, ws, nearest.data(), depth.data(), nullptr, level);
        EXPECT_EQ(nearest, reference.triangle) << simd_level_name(level);
        // A second frame with the same workspace draws the same (nothing left over).
        std::vector<float> depth_only(nearest.size());
        zbuffer_draw(triangles, w, h, ws, nullptr, depth_only.data(), nullptr, level);
        EXPECT_EQ(depth_only, depth) << simd_level_name(level);
    }
}

TEST(ZBufferTile, TheBufferDoesNotDependOnTheThreadCount) {
    const int w = 640, h = 360;
    const auto triangles = random_triangles(w, h, 40000, 11);  // several bin chunks
    std::vector<uint32_t> one(static_cast<size_t>(w) * h), two(one.size());
    {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        ZBufferWorkspace ws;
        zbuffer_draw(triangles, w, h, ws, one.data(), nullptr);
    }
    {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        ZBufferWorkspace ws;
        zbuffer_draw(triangles, w, h, ws, two.data(), nullptr);
    }
    EXPECT_EQ(one, two);
    // Later triangles win only when strictly nearer: the duplicated ones never show.
    for (const uint32_t t : one)
        if (t != k_no_triangle && t > 0)
            EXPECT_FALSE(triangles[t].v[0].position == triangles[t - 1].v[0].position &&
                         triangles[t].v[1].position == triangles[t - 1].v[1].position);
}

TEST(ZBufferTile, IndexedTrianglesDrawAsTheTrianglesTheyStandFor) {
    const int w = 160, h = 96;
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<ScreenVertex> vertices(300);
    for (ScreenVertex& v : vertices) {
        v.position = {unit(rng) * w, unit(rng) * h, 0.0f};
        v.inv_w = 0.2f + unit(rng);
    }
    std::vector<std::array<uint32_t, 3>> indices(900);
    for (auto& idx : indices)
        for (uint32_t& i : idx) i = static_cast<uint32_t>(rng() % vertices.size());
    const IndexedScreenTriangles indexed{vertices.data(), indices.data(), indices.size()};
    std::vector<ScreenTriangle> stored;
    for (size_t t = 0; t < indices.size(); ++t) stored.push_back(indexed[t]);
    ZBufferWorkspace ws;
    std::vector<uint32_t> a(static_cast<size_t>(w) * h), b(a.size());
    std::vector<float> da(a.size()), db(a.size());
    zbuffer_draw(stored, w, h, ws, a.data(), da.data());
    zbuffer_draw(indexed, w, h, ws, b.data(), db.data());
    EXPECT_EQ(a, b);
    EXPECT_EQ(da, db);
    size_t covered = 0;
    for (const uint32_t t : a) covered += t != k_no_triangle;
    EXPECT_GT(covered, a.size() / 2);
}

TEST(ZBufferTile, AnOccludedTriangleIsRejectedWithoutChangingTheBuffer) {
    // A near square covering a tile, then a far triangle inside it: hierarchical rejection may
    // skip the far one; nothing of it may show either way.
    std::vector<ScreenTriangle> triangles;
    auto add = [&](Vec3 a, Vec3 b, Vec3 c, float inv_w) {
        triangles.push_back(
            {{ScreenVertex{a, inv_w}, ScreenVertex{b, inv_w}, ScreenVertex{c, inv_w}},
             static_cast<uint32_t>(triangles.size())});
    };
    add({-1, -1, 0}, {40, -1, 0}, {-1, 40, 0}, 2.0f);
    add({40, -1, 0}, {40, 40, 0}, {-1, 40, 0}, 2.0f);
    add({2, 2, 0}, {14, 2, 0}, {2, 14, 0}, 0.5f);
    for (const SimdLevel level : supported_simd_levels()) {
        ZBufferWorkspace ws;
        std::vector<uint32_t> nearest(32 * 32);
        zbuffer_draw(triangles, 32, 32, ws, nearest.data(), nullptr, nullptr, level);
        for (const uint32_t t : nearest) EXPECT_LT(t, 2u) << simd_level_name(level);
    }
}

}  // namespace
}  // namespace hikari
