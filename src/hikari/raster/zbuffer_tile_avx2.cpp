// The Z-buffer tile kernel (zbuffer_tile_kernel.h) compiled for AVX2; chosen at run time by
// zbuffer_tile_kernel(). Everything shared is included before the target pragma.
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>

#include "hikari/raster/zbuffer_tile.h"

#if HIKARI_SIMD_KERNELS
#pragma GCC target("avx2,popcnt,bmi,bmi2,lzcnt")
#define HIKARI_ZBUFFER_AVX2 1
#include "hikari/raster/zbuffer_tile_kernel.h"

namespace hikari::detail {

void zbuffer_tile_avx2(const HalfSpaceTriangle* setup, const uint32_t* triangles, size_t count,
                       TileDepth& target) {
    zbuffer_tile_body(setup, triangles, count, target);
}

}  // namespace hikari::detail
#else
namespace hikari::detail {
// Never called: best_simd_level() is portable where the kernels are not compiled.
void zbuffer_tile_avx2(const HalfSpaceTriangle* setup, const uint32_t* triangles, size_t count,
                       TileDepth& target) {
    zbuffer_tile_portable(setup, triangles, count, target);
}
}  // namespace hikari::detail
#endif
