#include "hikari/core/simd_level.h"

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

SimdLevel best_simd_level() {
    static const SimdLevel best = simd_level_supported(SimdLevel::avx512) ? SimdLevel::avx512
                                  : simd_level_supported(SimdLevel::avx2) ? SimdLevel::avx2
                                                                          : SimdLevel::portable;
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
