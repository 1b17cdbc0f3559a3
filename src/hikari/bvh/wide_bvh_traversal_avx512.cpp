// The wide-BVH kernel compiled for AVX-512 (chosen at run time by wide_bvh_traversal.cpp).
// Everything the kernel includes comes first, compiled for the baseline; the kernel itself
// follows the target pragma and has internal linkage, so no AVX-512 code leaks into shared
// inline functions.
#include <immintrin.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "hikari/bvh/sphere_bvh.h"
#include "hikari/bvh/triangle_hit.h"
#include "hikari/bvh/wide_bvh.h"
#include "hikari/core/ray.h"
#include "hikari/core/simd_level.h"
#include "hikari/geometry/intersect.h"
#include "hikari/geometry/triangle_intersect.h"

#if HIKARI_SIMD_KERNELS
#pragma GCC target("avx2,avx512f,avx512vl,avx512dq,avx512bw,popcnt,bmi,bmi2,lzcnt")
#define HIKARI_SIMD8_AVX512 1
#include "hikari/bvh/wide_bvh_simd8.h"

namespace hikari::detail {

bool wide_closest_avx512(const WideBvh& bvh, const Ray& ray, Interval valid, TriangleHit& hit) {
    wide_kernel::LeafHit h;
    if (!wide_kernel::traverse<wide_kernel::Simd8Ops>(bvh, ray, valid, h)) return false;
    hit = wide_kernel::to_triangle_hit(bvh, h);
    return true;
}

bool wide_any_avx512(const WideBvh& bvh, const Ray& ray, Interval valid) {
    return wide_kernel::occluded<wide_kernel::Simd8Ops>(bvh, ray, valid);
}

bool wide_closest_sphere_avx512(const SphereBvh& bvh, const Ray& ray, Interval valid,
                                SphereHit& hit) {
    return wide_kernel::closest_sphere<wide_kernel::Simd8Ops>(bvh, ray, valid, hit);
}

bool wide_any_sphere_avx512(const SphereBvh& bvh, const Ray& ray, Interval valid) {
    return wide_kernel::any_sphere<wide_kernel::Simd8Ops>(bvh, ray, valid);
}

}  // namespace hikari::detail
#endif
