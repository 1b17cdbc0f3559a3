// The Whitted shading lanes (whitted_shade_kernel.h) compiled for AVX-512 and vectorised by the
// compiler; chosen at run time by whitted_shade.cpp. Everything shared is included before the
// target pragma, so only the kernel's internal-linkage functions get AVX-512 code.
#include <cstdint>
#include <vector>

#include "hikari/integrators/whitted/primary_hits.h"
#include "hikari/integrators/whitted/whitted_shade.h"

#if HIKARI_SIMD_KERNELS
#pragma GCC target( \
    "avx2,avx512f,avx512vl,avx512dq,avx512bw,popcnt,bmi,bmi2,lzcnt,prefer-vector-width=512")
#define HIKARI_KERNEL_LANES 16
#include "hikari/integrators/whitted/whitted_shade_kernel.h"

namespace hikari::detail {
void shade_lanes_avx512(const WhittedScene& scene, int spawn, int count, BlockLanes& lanes) {
    shade_kernel(scene, spawn, count, lanes);
}
}  // namespace hikari::detail
#else
namespace hikari::detail {
// Never called: best_simd_level() is portable where the kernels are not compiled.
void shade_lanes_avx512(const WhittedScene& scene, int spawn, int count, BlockLanes& lanes) {
    shade_lanes_portable(scene, spawn, count, lanes);
}
}  // namespace hikari::detail
#endif
