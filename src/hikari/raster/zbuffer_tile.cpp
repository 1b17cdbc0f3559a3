// The portable build of the Z-buffer tile kernel (zbuffer_tile_kernel.h).
#include "hikari/raster/zbuffer_tile_kernel.h"

namespace hikari::detail {

void zbuffer_tile_portable(const HalfSpaceTriangle* setup, const uint32_t* triangles, size_t count,
                           TileDepth& target) {
    zbuffer_tile_body(setup, triangles, count, target);
}

}  // namespace hikari::detail
