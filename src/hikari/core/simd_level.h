#pragma once
// Which SIMD instruction set the hot loops use, chosen at run time: the binary runs on any
// x86-64 (or other) CPU and uses AVX2 or AVX-512 where the CPU and OS support them.

/// 1 where the AVX2 / AVX-512 kernels are compiled in: x86-64 with GCC, whose
/// `#pragma GCC target` they use (clang, e.g. in the fuzzing build, gets the portable path only).
#if defined(__x86_64__) && !defined(__clang__)
#define HIKARI_SIMD_KERNELS 1
#else
#define HIKARI_SIMD_KERNELS 0
#endif

#include <vector>

namespace hikari {

/// The instruction sets the traversal kernels are compiled for. Every level gives bit-identical
/// answers; they differ only in speed.
enum class SimdLevel { portable, avx2, avx512 };

/// The best level this CPU supports (checked once, cached).
SimdLevel best_simd_level();

/// True when this CPU can run `level`.
bool simd_level_supported(SimdLevel level);

/// Every level this CPU can run, portable first (tests compare them all).
std::vector<SimdLevel> supported_simd_levels();

/// A short name: "portable", "avx2" or "avx512".
const char* simd_level_name(SimdLevel level);

/// The one of a function's three builds (portable, AVX2, AVX-512) that runs at `level`.
template <class Function>
Function* simd_pick(SimdLevel level, Function* portable, Function* avx2, Function* avx512) {
    switch (level) {
        case SimdLevel::avx512:
            return avx512;
        case SimdLevel::avx2:
            return avx2;
        default:
            return portable;
    }
}

}  // namespace hikari
