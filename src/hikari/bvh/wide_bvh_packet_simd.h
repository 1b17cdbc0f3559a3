#pragma once
// The 16-lane operations of the packet kernel (wide_bvh_packet_kernel.h): one zmm register per
// value with AVX-512, two ymm registers with AVX2. Include only after `#pragma GCC target` in
// the kernel's own translation unit (see wide_bvh_packet_avx512.cpp), which defines
// HIKARI_PACKET_AVX512 for the AVX-512 version: g++ does not define __AVX512F__ after the pragma
// in C++, so the target's own macros cannot choose. Every operation is an IEEE-exact add, sub, mul,
// div, min or max, no FMA, so the answers are bit-identical to the portable kernel's.

#include <immintrin.h>

#include "hikari/bvh/wide_bvh_packet_kernel.h"

namespace hikari::packet_kernel {
namespace {

#if HIKARI_PACKET_AVX512
#define HIKARI_CMP8(a, b, op) static_cast<uint32_t>(_mm256_cmp_ps_mask(a, b, op))
#else
#define HIKARI_CMP8(a, b, op) static_cast<uint32_t>(_mm256_movemask_ps(_mm256_cmp_ps(a, b, op)))
#endif

/// The frustum against a node's eight boxes (Frustum's bounds), 8 lanes = 8 children.
inline uint32_t test_frustum_simd8(const WideBvhNode& node, const Frustum& f, float t_lo,
                                   float t_hi, float* entry) {
    __m256 t0 = _mm256_set1_ps(t_lo), t1 = _mm256_set1_ps(t_hi);
    for (int a = 0; a < 3; ++a) {
        const __m256 lo = _mm256_set1_ps(f.inv_lo[a]), hi = _mm256_set1_ps(f.inv_hi[a]);
        const __m256 dn = _mm256_sub_ps(_mm256_load_ps(node.bounds[f.near_row[a]].data()),
                                        _mm256_set1_ps(f.o_near[a]));
        t0 = _mm256_max_ps(_mm256_min_ps(_mm256_mul_ps(dn, lo), _mm256_mul_ps(dn, hi)), t0);
        const __m256 df = _mm256_sub_ps(_mm256_load_ps(node.bounds[f.far_row[a]].data()),
                                        _mm256_set1_ps(f.o_far[a]));
        t1 = _mm256_min_ps(_mm256_max_ps(_mm256_mul_ps(df, lo), _mm256_mul_ps(df, hi)), t1);
    }
    _mm256_store_ps(entry, t0);
    return HIKARI_CMP8(t0, _mm256_mul_ps(t1, _mm256_set1_ps(k_exit_scale)), _CMP_LE_OQ);
}

#if HIKARI_PACKET_AVX512

struct Simd16Ops {
    using V = __m512;
    static V load(const float* p) { return _mm512_load_ps(p); }
    static void store(float* p, V a) { _mm512_store_ps(p, a); }
    static V set1(float x) { return _mm512_set1_ps(x); }
    static V add(V a, V b) { return _mm512_add_ps(a, b); }
    static V sub(V a, V b) { return _mm512_sub_ps(a, b); }
    static V mul(V a, V b) { return _mm512_mul_ps(a, b); }
    static V div(V a, V b) { return _mm512_div_ps(a, b); }
    static V min(V a, V b) { return _mm512_min_ps(a, b); }
    static V max(V a, V b) { return _mm512_max_ps(a, b); }
    static V abs(V a) { return _mm512_abs_ps(a); }
    static uint32_t sign(V a) { return _mm512_movepi32_mask(_mm512_castps_si512(a)); }
    static uint32_t ge(V a, V b) { return _mm512_cmp_ps_mask(a, b, _CMP_GE_OQ); }
    static uint32_t lt(V a, V b) { return _mm512_cmp_ps_mask(a, b, _CMP_LT_OQ); }
    static uint32_t le(V a, V b) { return _mm512_cmp_ps_mask(a, b, _CMP_LE_OQ); }
    static uint32_t eq(V a, V b) { return _mm512_cmp_ps_mask(a, b, _CMP_EQ_OQ); }
    static uint32_t gt(V a, V b) { return _mm512_cmp_ps_mask(a, b, _CMP_GT_OQ); }
    static uint32_t neq(V a, V b) { return _mm512_cmp_ps_mask(a, b, _CMP_NEQ_UQ); }
    static V select(uint32_t m, V a, V b) { return _mm512_mask_blend_ps(__mmask16(m), b, a); }
    static void store_masked(uint32_t* p, uint32_t m, uint32_t x) {
        _mm512_mask_storeu_epi32(p, __mmask16(m), _mm512_set1_epi32(int(x)));
    }
    static float reduce_min(uint32_t m, V a) { return _mm512_mask_reduce_min_ps(__mmask16(m), a); }
    static float reduce_max(uint32_t m, V a) { return _mm512_mask_reduce_max_ps(__mmask16(m), a); }
    static uint32_t test_frustum(const WideBvhNode& node, const Frustum& f, float t_lo, float t_hi,
                                 float* entry) {
        return test_frustum_simd8(node, f, t_lo, t_hi, entry);
    }
};

#else

/// AVX2: a 16-lane value as two halves.
struct Simd16Ops {
    struct V {
        __m256 lo, hi;
    };
    static V load(const float* p) { return {_mm256_load_ps(p), _mm256_load_ps(p + 8)}; }
    static void store(float* p, V a) { _mm256_store_ps(p, a.lo), _mm256_store_ps(p + 8, a.hi); }
    static V set1(float x) { return {_mm256_set1_ps(x), _mm256_set1_ps(x)}; }
    static V add(V a, V b) { return {_mm256_add_ps(a.lo, b.lo), _mm256_add_ps(a.hi, b.hi)}; }
    static V sub(V a, V b) { return {_mm256_sub_ps(a.lo, b.lo), _mm256_sub_ps(a.hi, b.hi)}; }
    static V mul(V a, V b) { return {_mm256_mul_ps(a.lo, b.lo), _mm256_mul_ps(a.hi, b.hi)}; }
    static V div(V a, V b) { return {_mm256_div_ps(a.lo, b.lo), _mm256_div_ps(a.hi, b.hi)}; }
    static V min(V a, V b) { return {_mm256_min_ps(a.lo, b.lo), _mm256_min_ps(a.hi, b.hi)}; }
    static V max(V a, V b) { return {_mm256_max_ps(a.lo, b.lo), _mm256_max_ps(a.hi, b.hi)}; }
    template <int k_op>
    static uint32_t cmp(V a, V b) {
        return HIKARI_CMP8(a.lo, b.lo, k_op) | HIKARI_CMP8(a.hi, b.hi, k_op) << 8;
    }
    static V abs(V a) {
        const __m256 m = _mm256_castsi256_ps(_mm256_set1_epi32(0x7fffffff));
        return {_mm256_and_ps(a.lo, m), _mm256_and_ps(a.hi, m)};
    }
    static uint32_t sign(V a) {
        return uint32_t(_mm256_movemask_ps(a.lo)) | uint32_t(_mm256_movemask_ps(a.hi)) << 8;
    }
    static uint32_t ge(V a, V b) { return cmp<_CMP_GE_OQ>(a, b); }
    static uint32_t lt(V a, V b) { return cmp<_CMP_LT_OQ>(a, b); }
    static uint32_t le(V a, V b) { return cmp<_CMP_LE_OQ>(a, b); }
    static uint32_t eq(V a, V b) { return cmp<_CMP_EQ_OQ>(a, b); }
    static uint32_t gt(V a, V b) { return cmp<_CMP_GT_OQ>(a, b); }
    static uint32_t neq(V a, V b) { return cmp<_CMP_NEQ_UQ>(a, b); }
    /// Bits 0-7 of m as an 8-lane select mask.
    static __m256 lane_mask(uint32_t m) {
        const __m256i bits = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
        return _mm256_castsi256_ps(
            _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(int(m)), bits), bits));
    }
    static V select(uint32_t m, V a, V b) {
        return {_mm256_blendv_ps(b.lo, a.lo, lane_mask(m)),
                _mm256_blendv_ps(b.hi, a.hi, lane_mask(m >> 8))};
    }
    static void store_masked(uint32_t* p, uint32_t m, uint32_t x) {
        const __m256i v = _mm256_set1_epi32(int(x));
        _mm256_maskstore_epi32(reinterpret_cast<int*>(p), _mm256_castps_si256(lane_mask(m)), v);
        _mm256_maskstore_epi32(reinterpret_cast<int*>(p + 8),
                               _mm256_castps_si256(lane_mask(m >> 8)), v);
    }
    static float reduce_min(uint32_t m, V a) {
        alignas(32) float x[16];
        store(x, a);
        float r = k_infinity;
        for (; m != 0; m &= m - 1) r = std::min(r, x[std::countr_zero(m)]);
        return r;
    }
    static float reduce_max(uint32_t m, V a) {
        alignas(32) float x[16];
        store(x, a);
        float r = -k_infinity;
        for (; m != 0; m &= m - 1) r = std::max(r, x[std::countr_zero(m)]);
        return r;
    }
    static uint32_t test_frustum(const WideBvhNode& node, const Frustum& f, float t_lo, float t_hi,
                                 float* entry) {
        return test_frustum_simd8(node, f, t_lo, t_hi, entry);
    }
};

#endif

#undef HIKARI_CMP8

}  // namespace
}  // namespace hikari::packet_kernel
