#pragma once
// Bit-exact comparison of floats in tests: the SIMD kernels must give the bits the scalar code
// gives, where == would let -0 equal +0 and never let a NaN equal itself.

#include <bit>
#include <cstdint>

#include "hikari/core/vec.h"

namespace hikari::testing {

/// True when `a` and `b` have the same bits.
inline bool same_bits(float a, float b) {
    return std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b);
}

/// True when every component of `a` has the bits of the same component of `b`.
inline bool same_bits(Vec3 a, Vec3 b) {
    return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z);
}

}  // namespace hikari::testing
