#include "hikari/raster/shade_lanes.h"

#include "hikari/raster/shade_lanes_kernel.h"

namespace hikari::detail {

void shade_surface_lanes_portable(const LaneLighting& lighting, int count, SurfaceLanes& lanes) {
    shade_lanes_kernel(lighting, count, lanes);
}

}  // namespace hikari::detail
