// The packet kernel compiled for AVX-512 (chosen at run time by wide_bvh_packet.cpp). Everything
// the kernel includes comes first, compiled for the baseline; the kernel itself follows the
// target pragma and has internal linkage, so no AVX-512 code leaks into shared inline functions.
#include <immintrin.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "hikari/bvh/triangle_hit.h"
#include "hikari/bvh/wide_bvh.h"
#include "hikari/bvh/wide_bvh_packet.h"
#include "hikari/core/ray.h"
#include "hikari/core/simd_level.h"
#include "hikari/geometry/triangle_intersect.h"

#if HIKARI_SIMD_KERNELS
#pragma GCC target("avx2,avx512f,avx512vl,avx512dq,avx512bw,popcnt,bmi,bmi2,lzcnt")
// GCC 12's AVX-512 intrinsics read an intentionally undefined register (_mm512_undefined_ps)
// and then warn about it once inlined.
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#define HIKARI_PACKET_AVX512 1
#include "hikari/bvh/wide_bvh_packet_simd.h"

namespace hikari::detail {

uint32_t packet_closest_avx512(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                               uint32_t min_group, PacketHit& hits, uint32_t& single) {
    return packet_kernel::trace_packet<packet_kernel::Simd16Ops>(bvh, packet, active, min_group,
                                                                 hits, single);
}

uint32_t packet_occluded_avx512(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                                uint32_t min_group, uint32_t& single) {
    return packet_kernel::trace_packet_any<packet_kernel::Simd16Ops>(bvh, packet, active, min_group,
                                                                     single);
}

}  // namespace hikari::detail
#endif
