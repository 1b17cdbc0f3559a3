// The camera-ray front end's lane loops (primary_hits_kernel.h) compiled for AVX2 and vectorised
// by the compiler; chosen at run time by primary_hits.cpp. Everything shared is included before
// the target pragma, so only the kernel's internal-linkage functions get AVX2 code.
#include <cstdint>
#include <vector>

#include "hikari/ray/primary_hits.h"

#if HIKARI_SIMD_KERNELS
#pragma GCC target("avx2,popcnt,bmi,bmi2,lzcnt")
#define HIKARI_PRIMARY_AVX2 1
#include "hikari/ray/primary_hits_kernel.h"

namespace hikari::detail {

void primary_directions_avx2(const PrimaryCamera& cam, PrimaryLanes& lanes) {
    directions_kernel(cam, lanes);
}

void primary_analytic_avx2(const PrimaryAnalytic& a, int count, PrimaryLanes& lanes) {
    analytic_kernel(a, count, lanes);
}

void primary_shadows_avx2(const PrimaryShadowLight& light, const PrimaryAnalytic& casters,
                          int count, ShadowLanes& lanes) {
    shadow_kernel(light, casters, count, lanes);
}

}  // namespace hikari::detail
#else
namespace hikari::detail {
// Never called: best_simd_level() is portable where the kernels are not compiled.
void primary_directions_avx2(const PrimaryCamera& cam, PrimaryLanes& lanes) {
    primary_directions_portable(cam, lanes);
}
void primary_analytic_avx2(const PrimaryAnalytic& a, int count, PrimaryLanes& lanes) {
    primary_analytic_portable(a, count, lanes);
}
void primary_shadows_avx2(const PrimaryShadowLight& light, const PrimaryAnalytic& casters,
                          int count, ShadowLanes& lanes) {
    primary_shadows_portable(light, casters, count, lanes);
}
}  // namespace hikari::detail
#endif
