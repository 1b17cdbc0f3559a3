#pragma once
// Parallel loop over image tiles (oneTBB). Each pixel is computed independently of the tile
// split and the thread that runs it, so images are bit-identical for any thread count.

#include <algorithm>
#include <cstdint>

#include <tbb/blocked_range.h>

#include "hikari/core/cancel.h"
#include "hikari/core/error.h"
#include "hikari/core/parallel.h"
#include "hikari/frame/render_settings.h"
#include "hikari/frame/tile_share.h"

namespace hikari {

inline constexpr int k_tile_size = 16;

/// A rectangle of pixels [x0, x1) × [y0, y1).
struct Tile {
    int x0, y0, x1, y1;
};

/// The tiles of a width × height image, row-major.
inline int64_t tile_count(int width, int height) {
    return int64_t{(width + k_tile_size - 1) / k_tile_size} *
           ((height + k_tile_size - 1) / k_tile_size);
}

/// Tile `t` of a width × height image (row-major).
inline Tile tile_at(int64_t t, int width, int height) {
    const int tiles_x = (width + k_tile_size - 1) / k_tile_size;
    const int tx = static_cast<int>(t % tiles_x), ty = static_cast<int>(t / tiles_x);
    return {tx * k_tile_size, ty * k_tile_size, std::min(width, (tx + 1) * k_tile_size),
            std::min(height, (ty + 1) * k_tile_size)};
}

/// The pixels of the tiles `control` leaves this process (all of them without a share).
inline uint64_t owned_pixels(int width, int height, const RenderControl* control) {
    const uint64_t all = static_cast<uint64_t>(width) * static_cast<uint64_t>(height);
    if (!control || !control->share) return all;
    uint64_t owned = 0;
    for (int64_t t = 0, n = tile_count(width, height); t < n; ++t) {
        if (!control->share->owns(t)) continue;
        const Tile tile = tile_at(t, width, height);
        owned +=
            static_cast<uint64_t>(tile.x1 - tile.x0) * static_cast<uint64_t>(tile.y1 - tile.y0);
    }
    return owned;
}

/// Calls `fn(const Tile&)` for every tile of a width × height image, on all cores of the current
/// task arena; with a share in `control`, for this process's tiles only (frame/tile_share.h).
/// Reports each finished tile to `control` (unless `report_tiles` is false: a caller that loops
/// over the image several times counts its own work) and throws Interrupted once all running
/// tiles are done when `control->cancel` is set, or when the process is asked to stop
/// (core/cancel.h: SIGINT, Ctrl-C in Python), which also stops loops run without a control.
template <class TileFn>
void for_each_tile(int width, int height, RenderControl* control, TileFn&& fn,
                   bool report_tiles = true) {
    const int64_t count = tile_count(width, height);
    const TileShare* share = control ? control->share : nullptr;
    if (control && report_tiles)
        control->work_total = static_cast<uint64_t>(share ? share->owned_of(count) : count);
    hikari::parallel_for(tbb::blocked_range<int64_t>(0, count, 1),
                         [&](const tbb::blocked_range<int64_t>& range) {
                             for (int64_t t = range.begin(); t != range.end(); ++t) {
                                 if ((control && control->cancel.load(std::memory_order_relaxed)) ||
                                     cancel_requested())
                                     return;
                                 if (share && !share->owns(t)) continue;
                                 fn(tile_at(t, width, height));
                                 if (control && report_tiles)
                                     control->work_done.fetch_add(1, std::memory_order_relaxed);
                             }
                         });
    if ((control && control->cancel.load()) || cancel_requested()) throw Interrupted();
}

}  // namespace hikari
