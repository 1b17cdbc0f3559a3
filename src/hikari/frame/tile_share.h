#pragma once
// One image shared among processes (`mpirun -np N hikari render ...`, docs/distributed.md):
// process `part` of `parts` renders every parts-th tile of the camera's tile loop
// (frame/tiles.h), starting at its own. Interleaved tiles give every process a like mix of
// cheap sky and costly glass. A pixel is computed the same whichever process renders it (its
// samples are seeded by the pixel), so the tiles gathered into one framebuffer are, bit for bit,
// the image one process renders.

#include <cstdint>
#include <functional>
#include <span>

namespace hikari {

struct Framebuffer;

struct TileShare {
    int part = 0;   ///< this process, 0 ≤ part < parts
    int parts = 1;  ///< the processes sharing the image
    /// Called on every process once its tiles are rendered, before the post steps that read
    /// neighbouring pixels (depth-cue blur): it makes `fb` the whole image where it is wanted.
    std::function<void(Framebuffer& fb)> combine;
    /// Called on every process with its integer sums (the light tracer's fixed-point splats,
    /// which land on any tile); each then holds the sums over all processes. Integer sums are
    /// exact in any order, so the totals are one process's bit for bit.
    std::function<void(std::span<int64_t> sums)> sum_over_parts;

    /// Whether tile `tile` (row-major over the image's tiles) is this process's.
    bool owns(int64_t tile) const { return tile % parts == part; }
    /// Whether block `block` of the work that is not per tile (a run of light paths) is this
    /// process's.
    bool owns_block(uint64_t block) const {
        return block % static_cast<uint64_t>(parts) == uint64_t(part);
    }
    /// How many of `tile_count` tiles are this process's.
    int64_t owned_of(int64_t tile_count) const {
        return tile_count > part ? (tile_count - part + parts - 1) / parts : 0;
    }
};

}  // namespace hikari
