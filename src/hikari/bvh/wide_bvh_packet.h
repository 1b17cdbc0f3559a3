#pragma once
// Shooting coherent packets of up to 16 rays (a 4x4 pixel block of camera rays) through the
// wide BVH at once. Inner nodes are culled by interval arithmetic over the whole packet (a
// frustum test: Wald, Boulos & Shirley 2007, "Ray tracing deformable scenes using dynamic
// bounding volume hierarchies"; Reshetov 2005's shared-origin frusta), so a node costs one
// 8-wide test like a single ray; leaves are tested for every ray of the packet at once, with
// the watertight test of Woop et al. 2013. The answers are exactly those of the single-ray
// intersect_closest (wide_bvh_traversal.h): same triangle, bit-identical t, u and v, at every
// SIMD level.

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "hikari/bvh/triangle_hit.h"
#include "hikari/bvh/wide_bvh.h"
#include "hikari/core/ray.h"
#include "hikari/core/simd_level.h"

namespace hikari {

/// Rays per packet: one AVX-512 register of floats.
inline constexpr uint32_t k_packet_size = 16;

/// Up to 16 rays, structure-of-arrays. Which lanes are live is said by the `active` mask passed
/// with it; the other lanes may hold anything (they are loaded with the rest but never affect
/// an answer).
struct alignas(64) RayPacket {
    float origin[3][k_packet_size];     ///< origin[axis][lane]
    float direction[3][k_packet_size];  ///< direction[axis][lane]; need not be unit length
    float t_min[k_packet_size];         ///< the open interval (t_min, t_max) a hit must lie in
    float t_max[k_packet_size];

    /// Stores `ray` with interval `valid` in `lane`.
    void set(uint32_t lane, const Ray& ray, Interval valid) {
        for (int a = 0; a < 3; ++a)
            origin[a][lane] = ray.origin[a], direction[a][lane] = ray.direction[a];
        t_min[lane] = valid.min;
        t_max[lane] = valid.max;
    }
    /// Loads the 4x4 block of rays at `rays` (row-major, `stride` rays from one row to the
    /// next; lane 4 y + x holds ray (x, y)), clipped to `width` x `height` (at most 4 x 4), all
    /// with interval `valid`. Returns the mask of lanes loaded; the others keep their values.
    uint32_t load_block(const Ray* rays, size_t stride, uint32_t width, uint32_t height,
                        Interval valid) {
        for (uint32_t k = 0; k < k_packet_size; ++k) t_min[k] = valid.min, t_max[k] = valid.max;
        if (width >= 4 && height >= 4) {
            // The common full block, branch-free.
            for (uint32_t y = 0; y < 4; ++y)
                for (uint32_t x = 0; x < 4; ++x)
                    for (int a = 0; a < 3; ++a) {
                        origin[a][4 * y + x] = rays[y * stride + x].origin[a];
                        direction[a][4 * y + x] = rays[y * stride + x].direction[a];
                    }
            return (1u << k_packet_size) - 1;
        }
        uint32_t active = 0;
        for (uint32_t y = 0; y < std::min(height, 4u); ++y)
            for (uint32_t x = 0; x < std::min(width, 4u); ++x) {
                set(4 * y + x, rays[y * stride + x], valid);
                active |= 1u << (4 * y + x);
            }
        return active;
    }
    /// The ray in `lane`.
    Ray ray(uint32_t lane) const {
        return {{origin[0][lane], origin[1][lane], origin[2][lane]},
                {direction[0][lane], direction[1][lane], direction[2][lane]}};
    }
};

/// The nearest hits of a packet, structure-of-arrays; lane i is meaningful only where bit i of
/// the mask returned by intersect_closest_packet is set.
struct alignas(64) PacketHit {
    float t[k_packet_size];
    float u[k_packet_size];            ///< barycentric weight of the triangle's second vertex
    float v[k_packet_size];            ///< barycentric weight of the third vertex
    uint32_t triangle[k_packet_size];  ///< index of the triangle in the builder's input

    /// Lane i as the single-ray API reports it.
    TriangleHit hit(uint32_t lane) const { return {t[lane], u[lane], v[lane], triangle[lane]}; }
};

/// Finds, for every lane i set in `active`, the nearest triangle hit by ray i of `packet` inside
/// its open interval; returns the mask of lanes that hit (a subset of `active`) and fills
/// those lanes of `hits`. Lane i's answer equals intersect_closest(bvh, packet.ray(i), ...):
/// same triangle, bit-identical t, u, v. Fast when the rays are coherent (a pixel block of one
/// camera); any rays work (degenerate, zero direction components, mixed directions), mixed
/// ones at about the single-ray speed. Uses the CPU's best SIMD level.
uint32_t intersect_closest_packet(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                                  PacketHit& hits);

/// intersect_closest_packet with an explicit SIMD level (must be supported by this CPU).
uint32_t intersect_closest_packet(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                                  PacketHit& hits, SimdLevel level);

/// For every lane i set in `active`: whether some triangle lies inside ray i's open interval
/// (shadow rays). Returns the mask of those lanes, each exactly intersect_any(bvh,
/// packet.ray(i), ...)'s answer at every SIMD level. Fast for coherent rays, such as the
/// shadow rays of a row of camera hits toward one light (Boulos et al. 2007 trace shadow rays
/// as packets for that reason); any rays work. Uses the CPU's best SIMD level.
uint32_t occluded_packet(const WideBvh& bvh, const RayPacket& packet, uint32_t active);

/// occluded_packet with an explicit SIMD level (must be supported by this CPU).
uint32_t occluded_packet(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                         SimdLevel level);

/// A tile of camera rays: the nearest hit of each ray of a `width` x `height` block of rays
/// stored row-major, `stride` rays from one row to the next (an image's rows: stride = image
/// width), all with interval `valid`. Traced as 4x4 packets. found[y * stride + x] is 1 where
/// ray (x, y) hits, and then hits[y * stride + x] is its hit (as intersect_closest's); both
/// arrays are indexed like `rays`.
void intersect_closest_tile(const WideBvh& bvh, const Ray* rays, size_t stride, uint32_t width,
                            uint32_t height, Interval valid, TriangleHit* hits, uint8_t* found,
                            SimdLevel level = best_simd_level());

namespace detail {
/// intersect_closest_packet, with the smallest group of alike rays (same direction octant and
/// watertight axis order) traced as a packet; smaller groups go ray by ray. For the tests,
/// which set it to 1 to run the packet kernel on every group.
uint32_t intersect_closest_packet(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                                  PacketHit& hits, SimdLevel level, uint32_t min_group);
/// occluded_packet with the smallest group traced as a packet (see above).
uint32_t occluded_packet(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                         SimdLevel level, uint32_t min_group);
}  // namespace detail

}  // namespace hikari
