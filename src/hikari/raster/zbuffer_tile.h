#pragma once
// The Z-buffer's inner loop over one tile (Alg 4.2), in SIMD: edge functions and depth tests over
// rows of 8 pixels at once, with the same integer edge functions and the same float rounding as
// the per-pixel loop (raster/half_space.h's for_each_covered_pixel), so every instruction set
// gives the bit-identical buffer. Compiled three times (portable, AVX2, AVX-512) from
// zbuffer_tile_kernel.h and chosen at run time.

#include <cstddef>
#include <cstdint>

#include "hikari/core/simd_level.h"
#include "hikari/frame/tiles.h"
#include "hikari/raster/half_space.h"

namespace hikari {

/// One tile's Z-buffer: k_tile_size × k_tile_size depths and triangle indices, row-major from
/// the tile's top-left pixel, and the largest depth it holds (what hierarchical rejection
/// compares a triangle's nearest depth with).
struct TileDepth {
    const Tile* tile = nullptr;
    float* depth = nullptr;
    uint32_t* nearest = nullptr;  ///< may be null: a depth-only pass (shadow maps)
    float farthest = 0;           ///< ≥ every depth of the tile's pixels
    /// Fragments depth-tested so far (pixel centres covered by a triangle not rejected whole):
    /// Alg 4.2's inner loop count for `--stats`.
    uint64_t tested = 0;
};

/// Depth-tests the triangles `triangles[0, count)` (indices into `setup`, drawn in that order)
/// into `target`: a fragment replaces the stored depth when it is strictly nearer. Triangles
/// whose nearest depth is behind `target.farthest` are skipped whole.
using ZBufferTileKernel = void(const HalfSpaceTriangle* setup, const uint32_t* triangles,
                               size_t count, TileDepth& target);

namespace detail {
void zbuffer_tile_portable(const HalfSpaceTriangle* setup, const uint32_t* triangles, size_t count,
                           TileDepth& target);
void zbuffer_tile_avx2(const HalfSpaceTriangle* setup, const uint32_t* triangles, size_t count,
                       TileDepth& target);
void zbuffer_tile_avx512(const HalfSpaceTriangle* setup, const uint32_t* triangles, size_t count,
                         TileDepth& target);
}  // namespace detail

/// The kernel for `level`.
inline ZBufferTileKernel* zbuffer_tile_kernel(SimdLevel level) {
    return simd_pick(level, detail::zbuffer_tile_portable, detail::zbuffer_tile_avx2,
                     detail::zbuffer_tile_avx512);
}

}  // namespace hikari
