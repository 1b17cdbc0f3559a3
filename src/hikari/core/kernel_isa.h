#pragma once
// The pack type tag of a SIMD kernel file (core/lanes.h). A kernel file compiled for AVX2 or
// AVX-512 defines HIKARI_KERNEL_LANES (8 or 16: its vector registers' width in floats) before
// including its kernel header, after its `#pragma GCC target`; the portable build uses SSE2's 4.
// The tag lives in an anonymous namespace: every template instantiated on its packs has
// internal linkage, so one file's AVX-512 code can never stand in for another file's portable
// code of the same name.

#ifndef HIKARI_KERNEL_LANES
#define HIKARI_KERNEL_LANES 4
#endif

#include "hikari/core/lanes.h"

namespace hikari::detail {
namespace {

struct KernelIsa {
    static constexpr int k_width = HIKARI_KERNEL_LANES;
};

// The packs every kernel file works in.
using LaneF = LaneFloat<KernelIsa>;
using LaneI = LaneInt<KernelIsa>;
using LaneM = LaneMask<KernelIsa>;
constexpr int k_width = KernelIsa::k_width;

}  // namespace
}  // namespace hikari::detail
