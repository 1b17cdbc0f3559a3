// The raster shading lanes (shade_lanes_kernel.h) compiled for AVX2 and vectorised by the
// compiler; chosen at run time by shade_lanes.h. Everything shared is included before the
// target pragma, so only the kernel's internal-linkage functions get AVX2 code.
#include <cstdint>

#include "hikari/core/lanes.h"
#include "hikari/raster/shade_lanes.h"
#include "hikari/shading/direct.h"
#include "hikari/shading/material_eval.h"

#if HIKARI_SIMD_KERNELS
#pragma GCC target("avx2,popcnt,bmi,bmi2,lzcnt")
#define HIKARI_KERNEL_LANES 8
#include "hikari/raster/shade_lanes_kernel.h"

namespace hikari::detail {
void shade_surface_lanes_avx2(const LaneLighting& lighting, int count, SurfaceLanes& lanes) {
    shade_lanes_kernel(lighting, count, lanes);
}
}  // namespace hikari::detail
#else
namespace hikari::detail {
// Never called: best_simd_level() is portable where the kernels are not compiled.
void shade_surface_lanes_avx2(const LaneLighting& lighting, int count, SurfaceLanes& lanes) {
    shade_surface_lanes_portable(lighting, count, lanes);
}
}  // namespace hikari::detail
#endif
