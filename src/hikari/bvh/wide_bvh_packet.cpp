#include "hikari/bvh/wide_bvh_packet.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "hikari/bvh/wide_bvh_packet_kernel.h"
#include "hikari/bvh/wide_bvh_traversal.h"

namespace hikari {
namespace detail {
// Defined in wide_bvh_packet_avx2.cpp and wide_bvh_packet_avx512.cpp.
uint32_t packet_closest_avx2(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                             uint32_t min_group, PacketHit& hits, uint32_t& single);
uint32_t packet_closest_avx512(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                               uint32_t min_group, PacketHit& hits, uint32_t& single);
uint32_t packet_occluded_avx2(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                              uint32_t min_group, uint32_t& single);
uint32_t packet_occluded_avx512(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                                uint32_t min_group, uint32_t& single);
}  // namespace detail

namespace {

using packet_kernel::Frustum;

/// The portable kernel: the same operations one lane at a time.
struct PortableOps {
    struct V {
        float x[k_packet_size];
    };
    template <typename F>
    static V map(V a, V b, F f) {
        V r;
        for (uint32_t i = 0; i < k_packet_size; ++i) r.x[i] = f(a.x[i], b.x[i]);
        return r;
    }
    template <typename F>
    static uint32_t mask(V a, V b, F f) {
        uint32_t m = 0;
        for (uint32_t i = 0; i < k_packet_size; ++i) m |= f(a.x[i], b.x[i]) ? 1u << i : 0u;
        return m;
    }
    static V load(const float* p) {
        V r;
        std::copy(p, p + k_packet_size, r.x);
        return r;
    }
    static void store(float* p, const V& a) { std::copy(a.x, a.x + k_packet_size, p); }
    static V set1(float s) {
        V r;
        std::fill(r.x, r.x + k_packet_size, s);
        return r;
    }
    static V add(V a, V b) {
        return map(a, b, [](float x, float y) { return x + y; });
    }
    static V sub(V a, V b) {
        return map(a, b, [](float x, float y) { return x - y; });
    }
    static V mul(V a, V b) {
        return map(a, b, [](float x, float y) { return x * y; });
    }
    static V div(V a, V b) {
        return map(a, b, [](float x, float y) { return x / y; });
    }
    static V min(V a, V b) {
        return map(a, b, [](float x, float y) { return x < y ? x : y; });
    }
    static V max(V a, V b) {
        return map(a, b, [](float x, float y) { return x > y ? x : y; });
    }
    static V abs(V a) {
        for (float& x : a.x) x = std::abs(x);
        return a;
    }
    static uint32_t sign(const V& a) {
        uint32_t m = 0;
        for (uint32_t i = 0; i < k_packet_size; ++i) m |= std::signbit(a.x[i]) ? 1u << i : 0u;
        return m;
    }
    static uint32_t ge(V a, V b) {
        return mask(a, b, [](float x, float y) { return x >= y; });
    }
    static uint32_t lt(V a, V b) {
        return mask(a, b, [](float x, float y) { return x < y; });
    }
    static uint32_t le(V a, V b) {
        return mask(a, b, [](float x, float y) { return x <= y; });
    }
    static uint32_t eq(V a, V b) {
        return mask(a, b, [](float x, float y) { return x == y; });
    }
    static uint32_t gt(V a, V b) {
        return mask(a, b, [](float x, float y) { return x > y; });
    }
    static uint32_t neq(V a, V b) {
        return mask(a, b, [](float x, float y) { return x != y; });
    }
    static V select(uint32_t m, V a, V b) {
        for (uint32_t i = 0; i < k_packet_size; ++i)
            if (m & (1u << i)) b.x[i] = a.x[i];
        return b;
    }
    static void store_masked(uint32_t* p, uint32_t m, uint32_t x) {
        for (; m != 0; m &= m - 1) p[std::countr_zero(m)] = x;
    }
    static float reduce_min(uint32_t m, const V& a) {
        float r = k_infinity;
        for (; m != 0; m &= m - 1) r = std::min(r, a.x[std::countr_zero(m)]);
        return r;
    }
    static float reduce_max(uint32_t m, const V& a) {
        float r = -k_infinity;
        for (; m != 0; m &= m - 1) r = std::max(r, a.x[std::countr_zero(m)]);
        return r;
    }
    static uint32_t test_frustum(const WideBvhNode& node, const Frustum& f, float t_lo, float t_hi,
                                 float* entry) {
        uint32_t m = 0;
        for (uint32_t i = 0; i < k_wide_bvh_width; ++i) {
            float t0 = t_lo, t1 = t_hi;
            for (int a = 0; a < 3; ++a) {
                const float dn = node.bounds[f.near_row[a]][i] - f.o_near[a];
                const float n0 = dn * f.inv_lo[a], n1 = dn * f.inv_hi[a];
                const float near = n0 < n1 ? n0 : n1;
                t0 = near > t0 ? near : t0;
                const float df = node.bounds[f.far_row[a]][i] - f.o_far[a];
                const float f0 = df * f.inv_lo[a], f1 = df * f.inv_hi[a];
                const float far = f0 > f1 ? f0 : f1;
                t1 = far < t1 ? far : t1;
            }
            entry[i] = t0;
            if (t0 <= t1 * packet_kernel::k_exit_scale) m |= 1u << i;
        }
        return m;
    }
};

uint32_t packet_closest(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                        uint32_t min_group, PacketHit& hits, uint32_t& single, SimdLevel level) {
#if HIKARI_SIMD_KERNELS
    switch (level) {
        case SimdLevel::avx512:
            return detail::packet_closest_avx512(bvh, packet, active, min_group, hits, single);
        case SimdLevel::avx2:
            return detail::packet_closest_avx2(bvh, packet, active, min_group, hits, single);
        default:
            break;
    }
#endif
    (void)level;
    return packet_kernel::trace_packet<PortableOps>(bvh, packet, active, min_group, hits, single);
}

uint32_t packet_occluded(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                         uint32_t min_group, uint32_t& single, SimdLevel level) {
#if HIKARI_SIMD_KERNELS
    switch (level) {
        case SimdLevel::avx512:
            return detail::packet_occluded_avx512(bvh, packet, active, min_group, single);
        case SimdLevel::avx2:
            return detail::packet_occluded_avx2(bvh, packet, active, min_group, single);
        default:
            break;
    }
#endif
    (void)level;
    return packet_kernel::trace_packet_any<PortableOps>(bvh, packet, active, min_group, single);
}

/// Smallest group traced as a packet by default: below it, single rays are faster.
constexpr uint32_t k_min_group = 4;

}  // namespace

uint32_t detail::intersect_closest_packet(const WideBvh& bvh, const RayPacket& packet,
                                          uint32_t active, PacketHit& hits, SimdLevel level,
                                          uint32_t min_group) {
    active &= (1u << k_packet_size) - 1;
    if (bvh.empty() || active == 0) return 0;

    uint32_t single = 0;
    uint32_t found =
        packet_closest(bvh, packet, active, std::max(1u, min_group), hits, single, level);

    /* the rest one by one */
    for (uint32_t m = single; m != 0; m &= m - 1) {
        const auto lane = static_cast<uint32_t>(std::countr_zero(m));
        TriangleHit hit;
        if (intersect_closest(bvh, packet.ray(lane), {packet.t_min[lane], packet.t_max[lane]}, hit,
                              level)) {
            hits.t[lane] = hit.t, hits.u[lane] = hit.u, hits.v[lane] = hit.v;
            hits.triangle[lane] = hit.triangle;
            found |= 1u << lane;
        } else {
            found &= ~(1u << lane);
        }
    }
    return found;
}

uint32_t intersect_closest_packet(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                                  PacketHit& hits, SimdLevel level) {
    return detail::intersect_closest_packet(bvh, packet, active, hits, level, k_min_group);
}

uint32_t intersect_closest_packet(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                                  PacketHit& hits) {
    static const SimdLevel level = best_simd_level();
    return intersect_closest_packet(bvh, packet, active, hits, level);
}

uint32_t detail::occluded_packet(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                                 SimdLevel level, uint32_t min_group) {
    active &= (1u << k_packet_size) - 1;
    if (bvh.empty() || active == 0) return 0;
    uint32_t single = 0;
    uint32_t occluded =
        packet_occluded(bvh, packet, active, std::max(1u, min_group), single, level);
    /* the rest one by one */
    for (uint32_t m = single; m != 0; m &= m - 1) {
        const auto lane = static_cast<uint32_t>(std::countr_zero(m));
        if (intersect_any(bvh, packet.ray(lane), {packet.t_min[lane], packet.t_max[lane]}, level))
            occluded |= 1u << lane;
    }
    return occluded;
}

uint32_t occluded_packet(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                         SimdLevel level) {
    return detail::occluded_packet(bvh, packet, active, level, k_min_group);
}

uint32_t occluded_packet(const WideBvh& bvh, const RayPacket& packet, uint32_t active) {
    static const SimdLevel level = best_simd_level();
    return occluded_packet(bvh, packet, active, level);
}

void intersect_closest_tile(const WideBvh& bvh, const Ray* rays, size_t stride, uint32_t width,
                            uint32_t height, Interval valid, TriangleHit* hits, uint8_t* found,
                            SimdLevel level) {
    RayPacket packet{};  // lanes a clipped block leaves unset are still read (then ignored)
    PacketHit packet_hits;
    for (uint32_t y0 = 0; y0 < height; y0 += 4) {
        for (uint32_t x0 = 0; x0 < width; x0 += 4) {
            const uint32_t active =
                packet.load_block(rays + y0 * stride + x0, stride, width - x0, height - y0, valid);
            const uint32_t hit_mask =
                intersect_closest_packet(bvh, packet, active, packet_hits, level);
            for (uint32_t k = 0; k < k_packet_size; ++k) {
                if (!(active & (1u << k))) continue;
                const size_t i = (y0 + k / 4) * stride + x0 + k % 4;
                const bool hit = (hit_mask & (1u << k)) != 0;
                found[i] = hit ? 1 : 0;
                if (hit) hits[i] = packet_hits.hit(k);
            }
        }
    }
}

}  // namespace hikari
