#pragma once
// Sorting screen triangles into the image's tiles, so that each tile can be rasterized by one
// thread from the triangles that touch it, in their original order. The triangles are binned in
// fixed chunks, in parallel, each chunk into bins of its own (as llvmpipe's setup threads do);
// a tile reads the chunks in order, so the order is the triangles' for any thread count.

#include <cstdint>
#include <span>
#include <vector>

#include "hikari/raster/half_space.h"

namespace hikari {

/// Triangle indices per tile, chunk by chunk. Kept from frame to frame: binning the next frame
/// into the same TileBins reuses its storage.
struct TileBins {
    /// Triangles per chunk: a chunk's bins are built by one thread.
    static constexpr size_t k_chunk_triangles = 16384;

    /// One chunk's bins as compressed rows: the triangles of tile i are
    /// triangle[begin[i], begin[i + 1]), ascending.
    struct Chunk {
        std::vector<uint32_t> begin;
        std::vector<uint32_t> triangle;
    };

    int tiles_x = 0, tiles_y = 0;
    std::vector<Chunk> chunks;  ///< only the first `chunk_count` are this frame's
    size_t chunk_count = 0;

    /// The bin of the tile whose top-left pixel is (x0, y0).
    size_t tile_at(int x0, int y0) const;

    /// Calls `fn(triangle index)` for every triangle binned to tile `tile`, in ascending order.
    template <class Fn>
    void for_each(size_t tile, Fn&& fn) const {
        for (size_t c = 0; c < chunk_count; ++c) {
            const Chunk& chunk = chunks[c];
            for (uint32_t k = chunk.begin[tile]; k < chunk.begin[tile + 1]; ++k)
                fn(chunk.triangle[k]);
        }
    }

    /// Calls `fn(const uint32_t* triangles, size_t count)` for each chunk's run of the tile's
    /// triangles, in order (what a kernel loops over).
    template <class Fn>
    void for_each_run(size_t tile, Fn&& fn) const {
        for (size_t c = 0; c < chunk_count; ++c) {
            const Chunk& chunk = chunks[c];
            if (chunk.begin[tile + 1] > chunk.begin[tile])
                fn(chunk.triangle.data() + chunk.begin[tile],
                   size_t{chunk.begin[tile + 1] - chunk.begin[tile]});
        }
    }
};

/// home_tile's answers for a triangle not to be drawn, and for one whose bounds span tiles.
inline constexpr uint32_t k_no_tile = 0xffffffff;
inline constexpr uint32_t k_several_tiles = 0xfffffffe;

/// A triangle no larger than a tile lies in at most 2 × 2 tiles: its home names the top-left
/// one's bin in the low bits, and whether it reaches into the tile to the right and below.
inline constexpr uint32_t k_home_spans_right = 1u << 31;
inline constexpr uint32_t k_home_spans_down = 1u << 30;
inline constexpr uint32_t k_home_tile_bits = k_home_spans_down - 1;

/// Where the bounds of `t` (set up for a `width`-wide image) lie: for a triangle no larger than
/// a tile (most of a dense mesh), its tiles as above; else k_several_tiles. Binning the former
/// needs no more than this word: its setup is not read again.
uint32_t home_tile(const HalfSpaceTriangle& t, int width);

/// Bins every triangle of `setup` into the k_tile_size tiles (frame/tiles.h) of a width × height
/// image that it may cover, into `bins` (its storage reused). `home[i]` is home_tile of triangle
/// i, or k_no_tile to leave it out; computed where the setup is, it spares this pass reading the
/// setup of every one-tile triangle again.
void bin_triangles(std::span<const HalfSpaceTriangle> setup, std::span<const uint32_t> home,
                   int width, int height, TileBins& bins);

}  // namespace hikari
