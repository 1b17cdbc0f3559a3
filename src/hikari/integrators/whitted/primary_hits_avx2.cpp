// The camera-ray front end's lane loops (primary_hits_kernel.h) compiled for AVX2 and vectorised
// by the compiler; chosen at run time by primary_hits.cpp. Everything shared is included before
// the target pragma, so only the kernel's internal-linkage functions get AVX2 code.
#include <cstdint>
#include <vector>

#include "hikari/integrators/whitted/primary_hits.h"

#if HIKARI_SIMD_KERNELS
#pragma GCC target("avx2,popcnt,bmi,bmi2,lzcnt")
#define HIKARI_KERNEL_LANES 8
#include "hikari/integrators/whitted/primary_hits_kernel.h"

namespace hikari::detail {

void primary_directions_avx2(const PrimaryCamera& cam, int chunks, BlockLanes& lanes) {
    directions_kernel(cam, chunks, lanes);
}

void primary_analytic_avx2(const PrimaryAnalytic& a, int chunks, BlockLanes& lanes) {
    analytic_kernel(a, chunks, lanes);
}

void primary_describe_avx2(const PrimaryObjects& o, int chunks, BlockLanes& lanes) {
    describe_kernel(o, chunks, lanes);
}

void primary_shadows_avx2(const Light& light, const PrimaryAnalytic& casters, int chunks,
                          BlockLanes& lanes) {
    shadow_kernel(light, casters, chunks, lanes);
}

}  // namespace hikari::detail
#else
namespace hikari::detail {
// Never called: best_simd_level() is portable where the kernels are not compiled.
void primary_directions_avx2(const PrimaryCamera& cam, int chunks, BlockLanes& lanes) {
    primary_directions_portable(cam, chunks, lanes);
}
void primary_analytic_avx2(const PrimaryAnalytic& a, int chunks, BlockLanes& lanes) {
    primary_analytic_portable(a, chunks, lanes);
}
void primary_describe_avx2(const PrimaryObjects& o, int chunks, BlockLanes& lanes) {
    primary_describe_portable(o, chunks, lanes);
}
void primary_shadows_avx2(const Light& light, const PrimaryAnalytic& casters, int chunks,
                          BlockLanes& lanes) {
    primary_shadows_portable(light, casters, chunks, lanes);
}
}  // namespace hikari::detail
#endif
