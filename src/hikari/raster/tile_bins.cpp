#include "hikari/raster/tile_bins.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hikari/core/cancel.h"
#include "hikari/core/parallel.h"
#include "hikari/frame/tiles.h"

namespace hikari {

namespace {

/// Whether the triangle may cover a pixel centre of the tile whose top-left pixel is
/// (x0, y0): false when all four corner centres of the tile lie outside one edge, so that a
/// long thin triangle is not handed to every tile of its bounding box (shadow volume sides,
/// grazing floors).
bool may_cover_tile(const HalfSpaceTriangle& t, int x0, int y0) {
    const int64_t px0 = int64_t{x0} * k_subpixel_one + k_subpixel_one / 2;
    const int64_t py0 = int64_t{y0} * k_subpixel_one + k_subpixel_one / 2;
    const int64_t span = int64_t{k_tile_size - 1} * k_subpixel_one;
    for (int e = 0; e < 3; ++e) {
        const int a = (e + 1) % 3, b = (e + 2) % 3;
        const int64_t dx = t.x[b] - t.x[a], dy = t.y[b] - t.y[a];
        // E(p) = dx (p.y − a.y) − dy (p.x − a.x) + bias is affine: its largest value over the
        // tile's corner centres is at the corner that the edge's inward normal points to.
        const int64_t px = -dy > 0 ? px0 + span : px0;
        const int64_t py = dx > 0 ? py0 + span : py0;
        if (dx * (py - t.y[a]) - dy * (px - t.x[a]) + t.bias[e] < 0) return false;
    }
    return true;
}

/// The pixel columns [first, last] in which the triangle can cover a pixel centre of rows
/// [row0, row1], widened by a pixel on each side; false when it covers none of those rows:
/// the triangle cut to the band of the rows' centres, its x extent. A long thin triangle (a
/// shadow volume's side) then visits only the tiles along it, not its whole bounding box.
bool columns_in_rows(const HalfSpaceTriangle& t, int row0, int row1, int& first, int& last) {
    const auto one = static_cast<double>(k_subpixel_one);
    const double lo = (row0 + 0.5) * one;
    const double hi = (row1 + 0.5) * one;
    double x_min = std::numeric_limits<double>::infinity(), x_max = -x_min;
    auto take = [&](double x) {
        x_min = std::min(x_min, x);
        x_max = std::max(x_max, x);
    };
    for (int i = 0; i < 3; ++i) {
        const double ax = static_cast<double>(t.x[i]), ay = static_cast<double>(t.y[i]);
        const double bx = static_cast<double>(t.x[(i + 1) % 3]);
        const double by = static_cast<double>(t.y[(i + 1) % 3]);
        if (ay >= lo && ay <= hi) take(ax);
        for (const double y : {lo, hi})
            if ((ay - y) * (by - y) < 0.0) take(ax + (bx - ax) * (y - ay) / (by - ay));
    }
    if (!(x_min <= x_max)) return false;
    first = std::max(t.x0, static_cast<int>(std::floor(x_min / one - 0.5)) - 1);
    last = std::min(t.x1 - 1, static_cast<int>(std::ceil(x_max / one - 0.5)) + 1);
    return first <= last;
}

}  // namespace

size_t TileBins::tile_at(int x0, int y0) const {
    return static_cast<size_t>(y0 / k_tile_size) * tiles_x + x0 / k_tile_size;
}

uint32_t home_tile(const HalfSpaceTriangle& t, int width) {
    // Larger than a tile: its tiles are tested (for_tiles below).
    if (t.x1 - t.x0 > k_tile_size || t.y1 - t.y0 > k_tile_size) return k_several_tiles;
    const int tx = t.x0 / k_tile_size, ty = t.y0 / k_tile_size;
    const int tiles_x = (width + k_tile_size - 1) / k_tile_size;
    return static_cast<uint32_t>(ty * tiles_x + tx) |
           ((t.x1 - 1) / k_tile_size != tx ? k_home_spans_right : 0u) |
           ((t.y1 - 1) / k_tile_size != ty ? k_home_spans_down : 0u);
}

void bin_triangles(std::span<const HalfSpaceTriangle> setup, std::span<const uint32_t> home,
                   int width, int height, TileBins& bins) {
    bins.tiles_x = (width + k_tile_size - 1) / k_tile_size;
    bins.tiles_y = (height + k_tile_size - 1) / k_tile_size;
    const size_t tiles = static_cast<size_t>(bins.tiles_x) * bins.tiles_y;
    bins.chunk_count =
        (setup.size() + TileBins::k_chunk_triangles - 1) / TileBins::k_chunk_triangles;
    if (bins.chunks.size() < bins.chunk_count) bins.chunks.resize(bins.chunk_count);
    auto for_tiles = [&](const HalfSpaceTriangle& t, auto&& fn) {
        for (int ty = t.y0 / k_tile_size; ty <= (t.y1 - 1) / k_tile_size; ++ty) {
            int first = 0, last = 0;
            const int row0 = std::max(t.y0, ty * k_tile_size);
            const int row1 = std::min(t.y1 - 1, ty * k_tile_size + k_tile_size - 1);
            if (!columns_in_rows(t, row0, row1, first, last)) continue;
            for (int tx = first / k_tile_size; tx <= last / k_tile_size; ++tx)
                if (may_cover_tile(t, tx * k_tile_size, ty * k_tile_size))
                    fn(static_cast<size_t>(ty) * bins.tiles_x + tx);
        }
    };
    // A triangle no larger than a tile touches the one to four tiles its home names, untested.
    auto for_home_tiles = [&](uint32_t home, auto&& fn) {
        const uint32_t tile = home & k_home_tile_bits;
        fn(tile);
        if (home & k_home_spans_right) fn(tile + 1);
        if (home & k_home_spans_down) {
            fn(tile + bins.tiles_x);
            if (home & k_home_spans_right) fn(tile + bins.tiles_x + 1);
        }
    };
    hikari::parallel_for(size_t{0}, bins.chunk_count, [&](size_t c) {
        throw_if_cancelled();  // SIGINT, Ctrl-C in Python: once per chunk
        TileBins::Chunk& chunk = bins.chunks[c];
        const size_t first = c * TileBins::k_chunk_triangles;
        const size_t last = std::min(setup.size(), first + TileBins::k_chunk_triangles);
        chunk.begin.assign(tiles + 1, 0);
        for (size_t i = first; i < last; ++i) {
            if (home[i] == k_no_tile) continue;
            if (home[i] != k_several_tiles) {
                for_home_tiles(home[i], [&](size_t tile) { ++chunk.begin[tile + 1]; });
                continue;
            }
            for_tiles(setup[i], [&](size_t tile) { ++chunk.begin[tile + 1]; });
        }
        for (size_t k = 1; k < chunk.begin.size(); ++k) chunk.begin[k] += chunk.begin[k - 1];
        chunk.triangle.resize(chunk.begin.back());
        // Fill from the back, moving each tile's start back to its place as it fills: the
        // counts array doubles as the fill pointers.
        for (size_t i = last; i-- > first;) {
            if (home[i] == k_no_tile) continue;
            if (home[i] != k_several_tiles) {
                for_home_tiles(home[i], [&](size_t tile) {
                    chunk.triangle[--chunk.begin[tile + 1]] = static_cast<uint32_t>(i);
                });
                continue;
            }
            for_tiles(setup[i], [&](size_t tile) {
                chunk.triangle[--chunk.begin[tile + 1]] = static_cast<uint32_t>(i);
            });
        }
        // begin[t + 1] now holds the start of tile t; shift back by one.
        for (size_t k = 0; k < tiles; ++k) chunk.begin[k] = chunk.begin[k + 1];
        chunk.begin[tiles] = static_cast<uint32_t>(chunk.triangle.size());
    });
}

}  // namespace hikari
