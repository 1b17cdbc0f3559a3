#pragma once
// Sorting screen triangles into the image's tiles, so that each tile can be rasterized by one
// thread from the triangles that touch it, in their original order.

#include <cstdint>
#include <vector>

#include "hikari/raster/half_space.h"

namespace hikari {

/// Triangle indices per tile in a flat array (compressed rows), each tile's in ascending order.
struct TileBins {
    int tiles_x = 0, tiles_y = 0;
    std::vector<uint32_t> begin;  ///< tiles_x · tiles_y + 1 offsets into `triangle`
    std::vector<uint32_t> triangle;

    /// The bin of the tile whose top-left pixel is (x0, y0).
    size_t tile_at(int x0, int y0) const;
};

/// Bins every triangle of `setup` whose `valid` entry is non-zero into the k_tile_size tiles
/// (frame/tiles.h) of a width × height image that its bounding box touches.
TileBins bin_triangles(const std::vector<HalfSpaceTriangle>& setup,
                       const std::vector<uint8_t>& valid, int width, int height);

}  // namespace hikari
