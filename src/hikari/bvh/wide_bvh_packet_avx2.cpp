// The packet kernel compiled for AVX2 (chosen at run time by wide_bvh_packet.cpp). Everything
// the kernel includes comes first, compiled for the baseline; the kernel itself follows the
// target pragma and has internal linkage, so no AVX2 code leaks into shared inline functions.
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
#pragma GCC target("avx2,popcnt,bmi,bmi2,lzcnt")
#define HIKARI_PACKET_AVX512 0
#include "hikari/bvh/wide_bvh_packet_simd.h"

namespace hikari::detail {

uint32_t packet_closest_avx2(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                             uint32_t min_group, PacketHit& hits, uint32_t& single) {
    return packet_kernel::trace_packet<packet_kernel::Simd16Ops>(bvh, packet, active, min_group,
                                                                 hits, single);
}

uint32_t packet_occluded_avx2(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                              uint32_t min_group, uint32_t& single) {
    return packet_kernel::trace_packet_any<packet_kernel::Simd16Ops>(bvh, packet, active, min_group,
                                                                     single);
}

}  // namespace hikari::detail
#endif
