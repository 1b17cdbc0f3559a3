#include "hikari/core/simd_level.h"

#include <cstdlib>
#include <string_view>

namespace hikari {

bool simd_level_supported(SimdLevel level) {
#if HIKARI_SIMD_KERNELS
    switch (level) {
        case SimdLevel::portable:
            return true;
        case SimdLevel::avx2:
            return __builtin_cpu_supports("avx2") != 0;
        case SimdLevel::avx512:
            return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("avx512f") &&
                   __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq") &&
                   __builtin_cpu_supports("avx512bw");
    }
    return false;
#else
    return level == SimdLevel::portable;
#endif
}

namespace {
/// The best level the CPU runs, capped by the environment variable HIKARI_SIMD (portable or
/// avx2), which lets one machine measure and test the narrower kernels.
SimdLevel pick_best_level() {
    SimdLevel best = simd_level_supported(SimdLevel::avx512) ? SimdLevel::avx512
                     : simd_level_supported(SimdLevel::avx2) ? SimdLevel::avx2
                                                             : SimdLevel::portable;
    if (const char* cap = std::getenv("HIKARI_SIMD")) {
        const std::string_view name(cap);
        if (name == "portable") best = SimdLevel::portable;
        if (name == "avx2" && best == SimdLevel::avx512) best = SimdLevel::avx2;
    }
    return best;
}
}  // namespace

SimdLevel best_simd_level() {
    static const SimdLevel best = pick_best_level();
    return best;
}

std::vector<SimdLevel> supported_simd_levels() {
    std::vector<SimdLevel> out;
    for (SimdLevel level : {SimdLevel::portable, SimdLevel::avx2, SimdLevel::avx512})
        if (simd_level_supported(level)) out.push_back(level);
    return out;
}

const char* simd_level_name(SimdLevel level) {
    switch (level) {
        case SimdLevel::avx2:
            return "avx2";
        case SimdLevel::avx512:
            return "avx512";
        default:
            return "portable";
    }
}

}  // namespace hikari
