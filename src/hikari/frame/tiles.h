#pragma once
// Parallel loop over image tiles (oneTBB). Each pixel is computed independently of the tile
// split and the thread that runs it, so images are bit-identical for any thread count.

#include <algorithm>
#include <cstdint>

#include <tbb/blocked_range.h>

#include "hikari/core/error.h"
#include "hikari/core/parallel.h"
#include "hikari/frame/render_settings.h"

namespace hikari {

inline constexpr int k_tile_size = 16;

/// A rectangle of pixels [x0, x1) × [y0, y1).
struct Tile {
    int x0, y0, x1, y1;
};

/// Calls `fn(const Tile&)` for every tile of a width × height image, on all cores of the current
/// task arena. Reports each finished tile to `control` (unless `report_tiles` is false: a
/// caller that loops over the image several times counts its own work) and throws Interrupted
/// once all running tiles are done when `control->cancel` is set.
template <class TileFn>
void for_each_tile(int width, int height, RenderControl* control, TileFn&& fn,
                   bool report_tiles = true) {
    const int tiles_x = (width + k_tile_size - 1) / k_tile_size;
    const int tiles_y = (height + k_tile_size - 1) / k_tile_size;
    const int64_t tile_count = int64_t{tiles_x} * tiles_y;
    if (control && report_tiles) control->work_total = static_cast<uint64_t>(tile_count);
    hikari::parallel_for(tbb::blocked_range<int64_t>(0, tile_count, 1),
                         [&](const tbb::blocked_range<int64_t>& range) {
                             for (int64_t t = range.begin(); t != range.end(); ++t) {
                                 if (control && control->cancel.load(std::memory_order_relaxed))
                                     return;
                                 const int tx = static_cast<int>(t % tiles_x);
                                 const int ty = static_cast<int>(t / tiles_x);
                                 const Tile tile{tx * k_tile_size, ty * k_tile_size,
                                                 std::min(width, (tx + 1) * k_tile_size),
                                                 std::min(height, (ty + 1) * k_tile_size)};
                                 fn(tile);
                                 if (control && report_tiles)
                                     control->work_done.fetch_add(1, std::memory_order_relaxed);
                             }
                         });
    if (control && control->cancel.load()) throw Interrupted();
}

}  // namespace hikari
