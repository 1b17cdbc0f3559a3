#include "hikari/raster/tile_bins.h"

#include "hikari/frame/tiles.h"

namespace hikari {

size_t TileBins::tile_at(int x0, int y0) const {
    return static_cast<size_t>(y0 / k_tile_size) * tiles_x + x0 / k_tile_size;
}

TileBins bin_triangles(const std::vector<HalfSpaceTriangle>& setup,
                       const std::vector<uint8_t>& valid, int width, int height) {
    TileBins bins;
    bins.tiles_x = (width + k_tile_size - 1) / k_tile_size;
    bins.tiles_y = (height + k_tile_size - 1) / k_tile_size;
    bins.begin.assign(static_cast<size_t>(bins.tiles_x) * bins.tiles_y + 1, 0);
    auto for_tiles = [&](const HalfSpaceTriangle& t, auto&& fn) {
        for (int ty = t.y0 / k_tile_size; ty <= (t.y1 - 1) / k_tile_size; ++ty)
            for (int tx = t.x0 / k_tile_size; tx <= (t.x1 - 1) / k_tile_size; ++tx)
                fn(static_cast<size_t>(ty) * bins.tiles_x + tx);
    };
    for (size_t i = 0; i < setup.size(); ++i)
        if (valid[i]) for_tiles(setup[i], [&](size_t tile) { ++bins.begin[tile + 1]; });
    for (size_t k = 1; k < bins.begin.size(); ++k) bins.begin[k] += bins.begin[k - 1];
    bins.triangle.resize(bins.begin.back());
    std::vector<uint32_t> fill(bins.begin.begin(), bins.begin.end() - 1);
    for (size_t i = 0; i < setup.size(); ++i)
        if (valid[i])
            for_tiles(setup[i],
                      [&](size_t tile) { bins.triangle[fill[tile]++] = static_cast<uint32_t>(i); });
    return bins;
}

}  // namespace hikari
