#pragma once
// The one pack the single-width lane tests use: 16 lanes, the widest the kernels use (AVX-512),
// split into SSE registers on the tests' baseline target.

#include "../core/test_isa.h"

namespace hikari::testing {

using TestIsa16 = TestIsa<16>;
inline constexpr int k_lanes16 = TestIsa16::k_width;

}  // namespace hikari::testing
