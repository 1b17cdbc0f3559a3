#pragma once
// One image shared among processes (`mpirun -np N hikari render ...`, docs/distributed.md):
// process `part` of `parts` renders every parts-th tile of the camera's tile loop
// (frame/tiles.h), starting at its own. Interleaved tiles give every process a like mix of
// cheap sky and costly glass. A pixel is computed the same whichever process renders it (its
// samples are seeded by the pixel), so the tiles gathered into one framebuffer are, bit for bit,
// the image one process renders.

#include <cstdint>
#include <functional>

namespace hikari {

struct Framebuffer;

struct TileShare {
    int part = 0;   ///< this process, 0 ≤ part < parts
    int parts = 1;  ///< the processes sharing the image
    /// Called on every process once its tiles are rendered, before the post steps that read
    /// neighbouring pixels (depth-cue blur): it makes `fb` the whole image where it is wanted.
    std::function<void(Framebuffer& fb)> combine;

    /// Whether tile `tile` (row-major over the image's tiles) is this process's.
    bool owns(int64_t tile) const { return tile % parts == part; }
    /// How many of `tile_count` tiles are this process's.
    int64_t owned_of(int64_t tile_count) const {
        return tile_count > part ? (tile_count - part + parts - 1) / parts : 0;
    }
};

}  // namespace hikari
