#include "hikari/bvh/wide_bvh_traversal.h"

#include "hikari/bvh/wide_bvh_kernel.h"

namespace hikari {
namespace detail {
// Defined in wide_bvh_traversal_avx2.cpp and wide_bvh_traversal_avx512.cpp.
bool wide_closest_avx2(const WideBvh& bvh, const Ray& ray, Interval valid, TriangleHit& hit);
bool wide_any_avx2(const WideBvh& bvh, const Ray& ray, Interval valid);
bool wide_closest_avx512(const WideBvh& bvh, const Ray& ray, Interval valid, TriangleHit& hit);
bool wide_any_avx512(const WideBvh& bvh, const Ray& ray, Interval valid);
bool wide_closest_sphere_avx2(const SphereBvh& bvh, const Ray& ray, Interval valid, SphereHit& hit);
bool wide_any_sphere_avx2(const SphereBvh& bvh, const Ray& ray, Interval valid);
bool wide_closest_sphere_avx512(const SphereBvh& bvh, const Ray& ray, Interval valid,
                                SphereHit& hit);
bool wide_any_sphere_avx512(const SphereBvh& bvh, const Ray& ray, Interval valid);
}  // namespace detail

namespace {

using wide_kernel::LeafHit;
using wide_kernel::LeafRay;
using wide_kernel::NodeRay;

/// The portable kernel: the same slab and watertight tests, one child or triangle at a time.
struct PortableOps {
    static uint32_t test_node(const WideBvhNode& node, const NodeRay& ray, float t_min, float t_max,
                              float* entry) {
        uint32_t mask = 0;
        for (uint32_t i = 0; i < k_wide_bvh_width; ++i) {
            float t0 = t_min, t1 = t_max;
            for (int a = 0; a < 3; ++a) {
                // Written as max(x, t) = x > t ? x : t so a NaN (ray in a face plane) loses.
                const float near =
                    (node.bounds[ray.near_row[a]][i] - ray.origin[a]) * ray.inv_dir[a];
                t0 = near > t0 ? near : t0;
            }
            for (int a = 0; a < 3; ++a) {
                const float far = (node.bounds[ray.far_row[a]][i] - ray.origin[a]) * ray.inv_dir[a];
                t1 = far < t1 ? far : t1;
            }
            entry[i] = t0;
            if (t0 <= t1 * wide_kernel::k_exit_scale) mask |= 1u << i;
        }
        return mask;
    }

    static uint32_t test_node_any(const WideBvhNode& node, const NodeRay& ray, float t_min,
                                  float t_max_far) {
        uint32_t mask = 0;
        for (uint32_t i = 0; i < k_wide_bvh_width; ++i) {
            float t0 = t_min, t1 = t_max_far;
            for (int a = 0; a < 3; ++a) {
                const float near =
                    (node.bounds[ray.near_row[a]][i] - ray.origin[a]) * ray.inv_dir[a];
                t0 = near > t0 ? near : t0;
            }
            for (int a = 0; a < 3; ++a) {
                const float far =
                    (node.bounds[ray.far_row[a]][i] - ray.origin[a]) * ray.inv_dir_far[a];
                t1 = far < t1 ? far : t1;
            }
            if (t0 <= t1) mask |= 1u << i;
        }
        return mask;
    }

    /// No filter: intersect_sphere itself rejects every sphere of the leaf it misses.
    static uint32_t sphere_candidates(const float*, uint32_t, uint32_t, const Ray&) {
        return 0xffu;
    }

    /// The reference test, one triangle at a time.
    class LeafTest {
      public:
        explicit LeafTest(const LeafRay& ray) : ray_(ray) {}
        template <bool k_any_hit>
        bool test(const float* block, uint32_t count, uint32_t first, Interval& valid,
                  LeafHit& hit) const {
            return wide_kernel::test_leaf_scalar<k_any_hit>(ray_, block, count, first, 0, count,
                                                            valid, hit);
        }

      private:
        const LeafRay& ray_;
    };
};

bool closest_portable(const WideBvh& bvh, const Ray& ray, Interval valid, TriangleHit& hit) {
    LeafHit h;
    if (!wide_kernel::traverse<PortableOps>(bvh, ray, valid, h)) return false;
    hit = wide_kernel::to_triangle_hit(bvh, h);
    return true;
}

bool any_portable(const WideBvh& bvh, const Ray& ray, Interval valid) {
    return wide_kernel::occluded<PortableOps>(bvh, ray, valid);
}

}  // namespace

bool intersect_closest(const WideBvh& bvh, const Ray& ray, Interval valid, TriangleHit& hit,
                       SimdLevel level) {
#if HIKARI_SIMD_KERNELS
    switch (level) {
        case SimdLevel::avx512:
            return detail::wide_closest_avx512(bvh, ray, valid, hit);
        case SimdLevel::avx2:
            return detail::wide_closest_avx2(bvh, ray, valid, hit);
        default:
            break;
    }
#endif
    return closest_portable(bvh, ray, valid, hit);
}

bool intersect_any(const WideBvh& bvh, const Ray& ray, Interval valid, SimdLevel level) {
#if HIKARI_SIMD_KERNELS
    switch (level) {
        case SimdLevel::avx512:
            return detail::wide_any_avx512(bvh, ray, valid);
        case SimdLevel::avx2:
            return detail::wide_any_avx2(bvh, ray, valid);
        default:
            break;
    }
#endif
    return any_portable(bvh, ray, valid);
}

bool intersect_closest(const WideBvh& bvh, const Ray& ray, Interval valid, TriangleHit& hit) {
    static const SimdLevel level = best_simd_level();
    return intersect_closest(bvh, ray, valid, hit, level);
}

bool intersect_any(const WideBvh& bvh, const Ray& ray, Interval valid) {
    static const SimdLevel level = best_simd_level();
    return intersect_any(bvh, ray, valid, level);
}

bool intersect_closest(const SphereBvh& bvh, const Ray& ray, Interval valid, SphereHit& hit,
                       SimdLevel level) {
#if HIKARI_SIMD_KERNELS
    switch (level) {
        case SimdLevel::avx512:
            return detail::wide_closest_sphere_avx512(bvh, ray, valid, hit);
        case SimdLevel::avx2:
            return detail::wide_closest_sphere_avx2(bvh, ray, valid, hit);
        default:
            break;
    }
#endif
    return wide_kernel::closest_sphere<PortableOps>(bvh, ray, valid, hit);
}

bool intersect_any(const SphereBvh& bvh, const Ray& ray, Interval valid, SimdLevel level) {
#if HIKARI_SIMD_KERNELS
    switch (level) {
        case SimdLevel::avx512:
            return detail::wide_any_sphere_avx512(bvh, ray, valid);
        case SimdLevel::avx2:
            return detail::wide_any_sphere_avx2(bvh, ray, valid);
        default:
            break;
    }
#endif
    return wide_kernel::any_sphere<PortableOps>(bvh, ray, valid);
}

bool intersect_closest(const SphereBvh& bvh, const Ray& ray, Interval valid, SphereHit& hit) {
    static const SimdLevel level = best_simd_level();
    return intersect_closest(bvh, ray, valid, hit, level);
}

bool intersect_any(const SphereBvh& bvh, const Ray& ray, Interval valid) {
    static const SimdLevel level = best_simd_level();
    return intersect_any(bvh, ray, valid, level);
}

}  // namespace hikari
