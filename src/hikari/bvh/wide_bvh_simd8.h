#pragma once
// The 8-wide SIMD operations of the wide-BVH kernel (see wide_bvh_kernel.h), for AVX2 and, with
// AVX-512VL mask compares, AVX-512. Include only after `#pragma GCC target` in the kernel's own
// translation unit, inside an anonymous namespace's reach (see wide_bvh_traversal_avx2.cpp).
// Every operation is an IEEE-exact add, sub, mul, div, min or max in the same order as the
// portable code, and no FMA is used, so the answers are bit-identical to it.

#include <immintrin.h>

#include "hikari/bvh/wide_bvh_kernel.h"

namespace hikari::wide_kernel {
namespace {

/// 8 lanes of a comparison as a bit mask. The AVX-512 translation unit defines
/// HIKARI_SIMD8_AVX512 itself: g++ 12 does not define __AVX512VL__ after `#pragma GCC target`.
#if defined(HIKARI_SIMD8_AVX512)
#define HIKARI_CMP_MASK(a, b, op) static_cast<uint32_t>(_mm256_cmp_ps_mask(a, b, op))
#else
#define HIKARI_CMP_MASK(a, b, op) static_cast<uint32_t>(_mm256_movemask_ps(_mm256_cmp_ps(a, b, op)))
#endif

/// Whether the leaf test is inlined into the walk (see Simd8Ops::LeafTest::test).
#if defined(HIKARI_SIMD8_AVX512)
#define HIKARI_LEAF_INLINE [[gnu::always_inline]] inline
#else
#define HIKARI_LEAF_INLINE [[gnu::noinline]]
#endif

struct Simd8Ops {
    static uint32_t test_node(const WideBvhNode& node, const NodeRay& ray, float t_min, float t_max,
                              float* entry) {
        const auto slab = [&](int a, const std::array<int, 3>& rows) {
            const __m256 b = _mm256_load_ps(node.bounds[rows[a]].data());
            return _mm256_mul_ps(_mm256_sub_ps(b, _mm256_set1_ps(ray.origin[a])),
                                 _mm256_set1_ps(ray.inv_dir[a]));
        };
        // max_ps(x, t) is x > t ? x : t, so a NaN slab distance loses, as in the portable code.
        __m256 t0 = _mm256_max_ps(slab(0, ray.near_row), _mm256_set1_ps(t_min));
        t0 = _mm256_max_ps(slab(1, ray.near_row), t0);
        t0 = _mm256_max_ps(slab(2, ray.near_row), t0);
        __m256 t1 = _mm256_min_ps(slab(0, ray.far_row), _mm256_set1_ps(t_max));
        t1 = _mm256_min_ps(slab(1, ray.far_row), t1);
        t1 = _mm256_min_ps(slab(2, ray.far_row), t1);
        _mm256_store_ps(entry, t0);
        return HIKARI_CMP_MASK(t0, _mm256_mul_ps(t1, _mm256_set1_ps(k_exit_scale)), _CMP_LE_OQ);
    }

    /// The any-hit slab test: no entry distances, exits widened through inv_dir_far (see
    /// k_far_scale); t_max_far is valid.max * k_far_scale.
    static uint32_t test_node_any(const WideBvhNode& node, const NodeRay& ray, float t_min,
                                  float t_max_far) {
        const auto slab = [&](int a, int row, float inv) {
            const __m256 b = _mm256_load_ps(node.bounds[row].data());
            return _mm256_mul_ps(_mm256_sub_ps(b, _mm256_set1_ps(ray.origin[a])),
                                 _mm256_set1_ps(inv));
        };
        __m256 t0 = _mm256_max_ps(slab(0, ray.near_row[0], ray.inv_dir[0]), _mm256_set1_ps(t_min));
        t0 = _mm256_max_ps(slab(1, ray.near_row[1], ray.inv_dir[1]), t0);
        t0 = _mm256_max_ps(slab(2, ray.near_row[2], ray.inv_dir[2]), t0);
        __m256 t1 =
            _mm256_min_ps(slab(0, ray.far_row[0], ray.inv_dir_far[0]), _mm256_set1_ps(t_max_far));
        t1 = _mm256_min_ps(slab(1, ray.far_row[1], ray.inv_dir_far[1]), t1);
        t1 = _mm256_min_ps(slab(2, ray.far_row[2], ray.inv_dir_far[2]), t1);
        return HIKARI_CMP_MASK(t0, t1, _CMP_LE_OQ);
    }

    /// Bit i clear only where sphere begin + i of a sphere leaf block (rows centre x, y, z and
    /// radius of `count` floats; sphere_bvh.h) surely misses `ray`: intersect_sphere's
    /// discriminant, by the same operations in the same order, is negative. Bits past the leaf
    /// are meaningless; the caller masks them.
    static uint32_t sphere_candidates(const float* block, uint32_t count, uint32_t begin,
                                      const Ray& ray) {
        const auto row = [&](uint32_t r) { return _mm256_loadu_ps(block + r * count + begin); };
        const __m256 fx = _mm256_sub_ps(_mm256_set1_ps(ray.origin.x), row(0));
        const __m256 fy = _mm256_sub_ps(_mm256_set1_ps(ray.origin.y), row(1));
        const __m256 fz = _mm256_sub_ps(_mm256_set1_ps(ray.origin.z), row(2));
        const __m256 dx = _mm256_set1_ps(ray.direction.x), dy = _mm256_set1_ps(ray.direction.y),
                     dz = _mm256_set1_ps(ray.direction.z);
        const __m256 f_dot_d = _mm256_add_ps(
            _mm256_add_ps(_mm256_mul_ps(fx, dx), _mm256_mul_ps(fy, dy)), _mm256_mul_ps(fz, dz));
        const __m256 b = _mm256_xor_ps(f_dot_d, _mm256_set1_ps(-0.0f));
        const __m256 px = _mm256_add_ps(fx, _mm256_mul_ps(dx, b));
        const __m256 py = _mm256_add_ps(fy, _mm256_mul_ps(dy, b));
        const __m256 pz = _mm256_add_ps(fz, _mm256_mul_ps(dz, b));
        const __m256 p2 = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(px, px), _mm256_mul_ps(py, py)),
                                        _mm256_mul_ps(pz, pz));
        const __m256 radius = row(3);
        const __m256 discriminant = _mm256_sub_ps(_mm256_mul_ps(radius, radius), p2);
        // Not less than 0 (NaN included): intersect_sphere decides.
        return HIKARI_CMP_MASK(discriminant, _mm256_setzero_ps(), _CMP_NLT_UQ);
    }

    /// Woop et al. 2013 on eight triangles of a leaf at once (the steps as in
    /// triangle_intersect.h), built once per ray: the ray's values are broadcast here, not at
    /// every leaf, and the rows of its axes are found by one multiplication each.
    class LeafTest {
      public:
        explicit LeafTest(const LeafRay& ray)
            : ray_(ray),
              kx_(ray.kx),
              ky_(ray.ky),
              kz_(ray.kz),
              ox_(_mm256_set1_ps(ray.ox)),
              oy_(_mm256_set1_ps(ray.oy)),
              oz_(_mm256_set1_ps(ray.oz)),
              sx_(_mm256_set1_ps(ray.sx)),
              sy_(_mm256_set1_ps(ray.sy)),
              sz_(_mm256_set1_ps(ray.sz)) {}

        /// The nearest (or any) triangle of the leaf inside valid; shrinks valid.max and fills
        /// hit for the nearest. With AVX-512's 32 registers the test is inlined into the walk
        /// and the ray's vectors stay in registers (any hit -8 to -10% time per ray; 2026-11-24).
        /// With AVX2's 16 it is kept out of line: inlined, its thirty-odd vector values crowd the
        /// node loop's registers and the per-node path fills with spills (any hit +2-3%).
        template <bool k_any_hit>
        HIKARI_LEAF_INLINE bool test(const float* block, uint32_t count, uint32_t first,
                                     Interval& valid, LeafHit& hit) const {
            // Leaves of at most eight triangles (the builder's default) are one block.
            const uint32_t lanes = count < 8 ? count : 8;
            const bool found = test_block<k_any_hit>(block, count, first, 0, lanes, valid, hit);
            if (count <= 8 || (k_any_hit && found)) return found;
            return test_rest<k_any_hit>(block, count, first, valid, hit) || found;
        }

      private:
        /// Triangles 8 to 15 of a leaf of more than eight: out of line, so that the walk's own
        /// code stays small.
        template <bool k_any_hit>
        [[gnu::noinline]] bool test_rest(const float* block, uint32_t count, uint32_t first,
                                         Interval& valid, LeafHit& hit) const {
            return test_block<k_any_hit>(block, count, first, 8, count - 8, valid, hit);
        }

        /// What steps 1-3 leave for the rest of the test, eight triangles a lane.
        struct Edges {
            __m256 az, bz, cz;  ///< vertices a, b, c: z relative to the origin, not yet scaled
            __m256 e0, e1, e2;  ///< edge functions (scaled barycentrics)
        };

        /// Steps 1-3 of Woop et al. 2013 for triangles [base, base + 8) of a leaf block: the
        /// vertices relative to the origin, sheared so the ray runs along +z, and the edge
        /// functions. (A function of its own, inlined: the generated code is the same.)
        [[gnu::always_inline]] Edges edge_functions(const float* block, uint32_t count,
                                                    uint32_t base) const {
            const uint32_t vertex_stride = 3 * count;  // from one vertex's rows to the next's
            const float* x_row = block + kx_ * count + base;
            const float* y_row = block + ky_ * count + base;
            const float* z_row = block + kz_ * count + base;
            const auto load = [&](const float* row, uint32_t vertex) {
                return _mm256_loadu_ps(row + vertex * vertex_stride);
            };
            /* steps 1-2: vertices relative to the origin, sheared so the ray runs along +z */
            const __m256 az = _mm256_sub_ps(load(z_row, 0), oz_);
            const __m256 bz = _mm256_sub_ps(load(z_row, 1), oz_);
            const __m256 cz = _mm256_sub_ps(load(z_row, 2), oz_);
            const __m256 ax =
                _mm256_sub_ps(_mm256_sub_ps(load(x_row, 0), ox_), _mm256_mul_ps(sx_, az));
            const __m256 ay =
                _mm256_sub_ps(_mm256_sub_ps(load(y_row, 0), oy_), _mm256_mul_ps(sy_, az));
            const __m256 bx =
                _mm256_sub_ps(_mm256_sub_ps(load(x_row, 1), ox_), _mm256_mul_ps(sx_, bz));
            const __m256 by =
                _mm256_sub_ps(_mm256_sub_ps(load(y_row, 1), oy_), _mm256_mul_ps(sy_, bz));
            const __m256 cx =
                _mm256_sub_ps(_mm256_sub_ps(load(x_row, 2), ox_), _mm256_mul_ps(sx_, cz));
            const __m256 cy =
                _mm256_sub_ps(_mm256_sub_ps(load(y_row, 2), oy_), _mm256_mul_ps(sy_, cz));
            /* step 3: scaled barycentrics */
            const __m256 e0 = _mm256_sub_ps(_mm256_mul_ps(cx, by), _mm256_mul_ps(cy, bx));
            const __m256 e1 = _mm256_sub_ps(_mm256_mul_ps(ax, cy), _mm256_mul_ps(ay, cx));
            const __m256 e2 = _mm256_sub_ps(_mm256_mul_ps(bx, ay), _mm256_mul_ps(by, ax));
            return {az, bz, cz, e0, e1, e2};
        }

        /// Triangles [base, base + lanes) of the leaf, lanes <= 8.
        template <bool k_any_hit>
        [[gnu::always_inline]] bool test_block(const float* block, uint32_t count, uint32_t first,
                                               uint32_t base, uint32_t lanes, Interval& valid,
                                               LeafHit& hit) const {
            const __m256 zero = _mm256_setzero_ps();
            const uint32_t lane_mask = (1u << lanes) - 1;
            /* steps 1-3: shear, scaled barycentrics */
            const auto [az, bz, cz, e0, e1, e2] = edge_functions(block, count, base);
            const uint32_t on_edge =
                (HIKARI_CMP_MASK(e0, zero, _CMP_EQ_OQ) | HIKARI_CMP_MASK(e1, zero, _CMP_EQ_OQ) |
                 HIKARI_CMP_MASK(e2, zero, _CMP_EQ_OQ)) &
                lane_mask;
            if (on_edge != 0) [[unlikely]] {
                // Sec 4's exact fallback is rare: run the reference test on these lanes.
                return test_leaf_scalar<k_any_hit>(ray_, block, count, first, base, base + lanes,
                                                   valid, hit);
            }
            /* step 4: inside when all edge functions share a sign */
            const uint32_t negative = HIKARI_CMP_MASK(e0, zero, _CMP_LT_OQ) |
                                      HIKARI_CMP_MASK(e1, zero, _CMP_LT_OQ) |
                                      HIKARI_CMP_MASK(e2, zero, _CMP_LT_OQ);
            const uint32_t positive = HIKARI_CMP_MASK(e0, zero, _CMP_GT_OQ) |
                                      HIKARI_CMP_MASK(e1, zero, _CMP_GT_OQ) |
                                      HIKARI_CMP_MASK(e2, zero, _CMP_GT_OQ);
            uint32_t inside = ~(negative & positive) & lane_mask;
            // A shadow ray goes on without this branch, which it would mispredict often: the
            // line through a leaf meets its triangles about as often as not, and without the
            // division the rest costs a few instructions (B2 +3-10%, docs/performance.md).
            if (!k_any_hit && inside == 0) return false;
            const __m256 det = _mm256_add_ps(_mm256_add_ps(e0, e1), e2);
            inside &= HIKARI_CMP_MASK(det, zero, _CMP_NEQ_UQ);
            /* step 5: the hit distance */
            const __m256 z0 = _mm256_mul_ps(e0, _mm256_mul_ps(sz_, az));
            const __m256 z1 = _mm256_mul_ps(e1, _mm256_mul_ps(sz_, bz));
            const __m256 z2 = _mm256_mul_ps(e2, _mm256_mul_ps(sz_, cz));
            const __m256 t_scaled = _mm256_add_ps(_mm256_add_ps(z0, z1), z2);
            {
                // Within rounding of the origin: no hit (triangle_intersect.h, k_t_rounding).
                const __m256 sign_bit = _mm256_set1_ps(-0.0f);
                const __m256 band =
                    _mm256_mul_ps(_mm256_set1_ps(k_t_rounding),
                                  _mm256_add_ps(_mm256_add_ps(_mm256_andnot_ps(sign_bit, z0),
                                                              _mm256_andnot_ps(sign_bit, z1)),
                                                _mm256_andnot_ps(sign_bit, z2)));
                inside &= HIKARI_CMP_MASK(_mm256_andnot_ps(sign_bit, t_scaled), band, _CMP_GT_OQ);
            }
            if constexpr (k_any_hit) {
                // scaled_distance_inside: no division for a shadow ray.
                const __m256 sign_bit = _mm256_set1_ps(-0.0f);
                const __m256 t_signed = _mm256_xor_ps(t_scaled, _mm256_and_ps(det, sign_bit));
                const __m256 abs_det = _mm256_andnot_ps(sign_bit, det);
                inside &=
                    HIKARI_CMP_MASK(_mm256_mul_ps(_mm256_set1_ps(valid.min), abs_det), t_signed,
                                    _CMP_LT_OQ) &
                    HIKARI_CMP_MASK(t_signed, _mm256_mul_ps(_mm256_set1_ps(valid.max), abs_det),
                                    _CMP_LT_OQ);
                return inside != 0;
            } else {
                const __m256 inv_det = _mm256_div_ps(_mm256_set1_ps(1.0f), det);
                const __m256 t = _mm256_mul_ps(t_scaled, inv_det);
                inside &= HIKARI_CMP_MASK(_mm256_set1_ps(valid.min), t, _CMP_LT_OQ) &
                          HIKARI_CMP_MASK(t, _mm256_set1_ps(valid.max), _CMP_LT_OQ);
                if (inside == 0) return false;
                take_nearest(t, e1, e2, inv_det, inside, first, base, valid, hit);
                return true;
            }
        }

        /// The nearest of the lanes `inside` (not empty), the lowest of equal ones, as the
        /// slot-order scalar loop: its distance, barycentrics (e1 and e2 times inv_det) and slot
        /// (lane i's is first + base + i) into `hit`, its distance into valid.max.
        [[gnu::always_inline]] static void take_nearest(__m256 t, __m256 e1, __m256 e2,
                                                        __m256 inv_det, uint32_t inside,
                                                        uint32_t first, uint32_t base,
                                                        Interval& valid, LeafHit& hit) {
            alignas(32) float ts[8];
            _mm256_store_ps(ts, t);
            uint32_t best = static_cast<uint32_t>(std::countr_zero(inside));
            for (uint32_t m = inside & (inside - 1); m != 0; m &= m - 1) {
                const auto i = static_cast<uint32_t>(std::countr_zero(m));
                if (ts[i] < ts[best]) best = i;
            }
            alignas(32) float us[8], vs[8];
            _mm256_store_ps(us, _mm256_mul_ps(e1, inv_det));
            _mm256_store_ps(vs, _mm256_mul_ps(e2, inv_det));
            hit = {ts[best], us[best], vs[best], first + base + best};
            valid.max = ts[best];
        }

        const LeafRay& ray_;     ///< for the exact fallback
        uint32_t kx_, ky_, kz_;  ///< its axes, kept in registers through the walk
        __m256 ox_, oy_, oz_, sx_, sy_, sz_;
    };
};

#undef HIKARI_CMP_MASK
#undef HIKARI_LEAF_INLINE

}  // namespace
}  // namespace hikari::wide_kernel
