#pragma once
// The lane loops of the camera-ray front end (primary_hits.h), written once and compiled by
// primary_hits.cpp (baseline x86-64), primary_hits_avx2.cpp and primary_hits_avx512.cpp (after
// their `#pragma GCC target`), which the compiler vectorises across 4, 8 or 16 rays. Each loop
// body is the scalar code's arithmetic (camera_ray, intersect_sphere, intersect_plane in
// ray/intersect.h) in the same order, with branches turned into selects, so every level rounds
// exactly as the scalar path does (-ffp-contract=off: no FMA). Only float arithmetic and
// builtins appear here, no shared inline functions, so no wider code can leak into them; the
// functions have internal linkage (one copy per including file).

#include <cstdint>

#include "hikari/ray/primary_hits.h"

namespace hikari::detail {
namespace {

constexpr int k_lanes = k_primary_block_rays;

/// camera_ray(frame, x + 0.5, y + 0.5) for every lane: direction = normalize(forward + x right +
/// y up) with x, y the pixel centre on the image plane one unit in front of the eye; no hit yet
/// (t = ∞, object 0).
[[maybe_unused]] void directions_kernel(const PrimaryCamera& cam, PrimaryLanes& lanes) {
    float* __restrict dx = lanes.direction[0];
    float* __restrict dy = lanes.direction[1];
    float* __restrict dz = lanes.direction[2];
    float* __restrict ox = lanes.origin[0];
    float* __restrict oy = lanes.origin[1];
    float* __restrict oz = lanes.origin[2];
    float* __restrict t = lanes.t;
    int32_t* __restrict object = lanes.object;
    const PrimaryCamera c = cam;  // a local copy: the stores below cannot change it
    for (int i = 0; i < k_lanes; ++i) {
        const int column = i % k_primary_block, row = i / k_primary_block;  // lane i's pixel
        const float px = static_cast<float>(c.x0 + column) + 0.5f;
        const float py = static_cast<float>(c.y0 + row) + 0.5f;
        const float x = (2.0f * px / c.width - 1.0f) * c.tan_half_fov_y * c.aspect;
        const float y = (1.0f - 2.0f * py / c.height) * c.tan_half_fov_y;
        const float vx = c.forward[0] + c.right[0] * x + c.up[0] * y;
        const float vy = c.forward[1] + c.right[1] * x + c.up[1] * y;
        const float vz = c.forward[2] + c.right[2] * x + c.up[2] * y;
        const float inv_length = 1.0f / __builtin_sqrtf(vx * vx + vy * vy + vz * vz);
        dx[i] = vx * inv_length;
        dy[i] = vy * inv_length;
        dz[i] = vz * inv_length;
        ox[i] = c.eye[0], oy[i] = c.eye[1], oz[i] = c.eye[2];
        t[i] = __builtin_inff(), object[i] = 0;
    }
}

/// intersect_sphere (Haines et al. 2019) for one lane on the range (0, limit): the distance of
/// the nearer hit inside the range, or NaN for none (also when q = 0: intersect_sphere takes both
/// roots as 0 there, which the open range never holds). f is origin - centre.
[[maybe_unused]] inline float sphere_lane(float fx, float fy, float fz, float dx, float dy,
                                          float dz, float r2, float limit) {
    const float b = -(fx * dx + fy * dy + fz * dz);
    const float qx = fx + dx * b, qy = fy + dy * b, qz = fz + dz * b;
    const float discriminant = r2 - (qx * qx + qy * qy + qz * qz);
    const float c = fx * fx + fy * fy + fz * fz - r2;
    const bool behind = c > 0.0f && b <= 0.0f;                  // both roots <= 0
    const float root = __builtin_sqrtf(discriminant);           // NaN when negative: no hit
    const float q = b + (__builtin_signbit(b) ? -root : root);  // copysign(root, b)
    const float t0 = c / q, t1 = q;
    const bool swap = t0 > t1;
    const float near = swap ? t1 : t0, far = swap ? t0 : t1;
    const bool near_in = 0.0f < near && near < limit;
    const bool far_in = 0.0f < far && far < limit;
    const bool hit = !(discriminant < 0.0f) && !behind && q != 0.0f && (near_in || far_in);
    return hit ? (near_in ? near : far) : __builtin_nanf("");
}

/// The nearest of the lanes' triangle hit (already in lanes.t / lanes.object), the spheres and
/// the planes, tested in SceneIntersector::closest's order: a later primitive wins only when
/// strictly nearer.
inline void analytic_chunk(const PrimaryAnalytic& a, PrimaryLanes& lanes, int base) {
    const float* __restrict ox = lanes.origin[0] + base;
    const float* __restrict oy = lanes.origin[1] + base;
    const float* __restrict oz = lanes.origin[2] + base;
    const float* __restrict dx = lanes.direction[0] + base;
    const float* __restrict dy = lanes.direction[1] + base;
    const float* __restrict dz = lanes.direction[2] + base;
    float* __restrict t_max = lanes.t + base;
    int32_t* __restrict object = lanes.object + base;
    const int32_t spheres = a.spheres, planes = a.planes;

    for (int32_t s = 0; s < spheres; ++s) {
        const float cx = a.sphere_center[0][s], cy = a.sphere_center[1][s],
                    cz = a.sphere_center[2][s];
        const float radius = a.sphere_radius[s];
        const float r2 = radius * radius;
        for (int i = 0; i < k_lane_chunk; ++i) {
            const float t =
                sphere_lane(ox[i] - cx, oy[i] - cy, oz[i] - cz, dx[i], dy[i], dz[i], r2, t_max[i]);
            const bool hit = t == t;
            t_max[i] = hit ? t : t_max[i];
            object[i] = hit ? 2 + s : object[i];
        }
    }
    for (int32_t p = 0; p < planes; ++p) {
        // intersect_plane, per lane.
        const float qx = a.plane_point[0][p], qy = a.plane_point[1][p], qz = a.plane_point[2][p];
        const float nx = a.plane_normal[0][p], ny = a.plane_normal[1][p], nz = a.plane_normal[2][p];
        for (int i = 0; i < k_lane_chunk; ++i) {
            const float denominator = nx * dx[i] + ny * dy[i] + nz * dz[i];
            const float t =
                ((qx - ox[i]) * nx + (qy - oy[i]) * ny + (qz - oz[i]) * nz) / denominator;
            const float limit = t_max[i];
            const bool hit = denominator != 0.0f && 0.0f < t && t < limit;
            t_max[i] = hit ? t : limit;
            object[i] = hit ? 2 + spheres + p : object[i];
        }
    }
}

/// analytic_chunk for every chunk of lanes that holds one of the first `count`.
[[maybe_unused]] void analytic_kernel(const PrimaryAnalytic& a, int count, PrimaryLanes& lanes) {
    for (int base = 0; base < count; base += k_lane_chunk) analytic_chunk(a, lanes, base);
}

/// offset_ray_origin (ray/ray_offset.h) for one coordinate: p moved by 256 n ulps away from
/// zero's side (the sign bit s of p gives -ulps as (ulps ^ s) - s; positions are finite, so the
/// sign bit is p < 0 except for -0, which the |p| < 1/32 branch takes), or by n / 65536 near
/// the origin.
[[maybe_unused]] inline float offset_origin_lane(float p, float n) {
    const auto ulps = static_cast<int32_t>(256.0f * n);
    const auto bits = __builtin_bit_cast(int32_t, p);
    const int32_t sign = bits >> 31;
    const float moved = __builtin_bit_cast(float, bits + ((ulps ^ sign) - sign));
    return __builtin_fabsf(p) < 1.0f / 32.0f ? p + 1.0f / 65536.0f * n : moved;
}

/// Shadow rays from the lanes' hit points toward one light: shade_local's sample_light, the
/// Wächter & Binder origin offset of offset_ray_origin (ray/ray_offset.h) and
/// SceneIntersector::occluded's sphere and plane tests, per lane. Sets bit `light_bit` of
/// lanes.lit where no shadow-casting sphere or plane blocks the ray.
inline void shadow_chunk(const PrimaryShadowLight& light, const PrimaryAnalytic& a,
                         ShadowLanes& lanes, int base) {
    const float* __restrict px = lanes.position[0] + base;
    const float* __restrict py = lanes.position[1] + base;
    const float* __restrict pz = lanes.position[2] + base;
    const float* __restrict nx = lanes.normal[0] + base;
    const float* __restrict ny = lanes.normal[1] + base;
    const float* __restrict nz = lanes.normal[2] + base;
    float* __restrict ox = lanes.origin[0] + base;
    float* __restrict oy = lanes.origin[1] + base;
    float* __restrict oz = lanes.origin[2] + base;
    float* __restrict dx = lanes.to_light[0] + base;
    float* __restrict dy = lanes.to_light[1] + base;
    float* __restrict dz = lanes.to_light[2] + base;
    float* __restrict distance = lanes.distance + base;
    int32_t* __restrict blocked = lanes.blocked + base;
    const PrimaryShadowLight l = light;
    for (int i = 0; i < k_lane_chunk; ++i) {
        ox[i] = offset_origin_lane(px[i], nx[i]);
        oy[i] = offset_origin_lane(py[i], ny[i]);
        oz[i] = offset_origin_lane(pz[i], nz[i]);
    }
    // sample_light: unit direction toward the light and the distance to it.
    if (l.directional) {
        for (int i = 0; i < k_lane_chunk; ++i) {
            dx[i] = l.to_light[0], dy[i] = l.to_light[1], dz[i] = l.to_light[2];
            distance[i] = __builtin_inff();
        }
    } else {
        for (int i = 0; i < k_lane_chunk; ++i) {
            const float vx = l.position[0] - px[i], vy = l.position[1] - py[i],
                        vz = l.position[2] - pz[i];
            const float dist = __builtin_sqrtf(vx * vx + vy * vy + vz * vz);
            const float inv = 1.0f / dist;
            dx[i] = vx * inv, dy[i] = vy * inv, dz[i] = vz * inv;
            distance[i] = dist;
        }
    }
    for (int i = 0; i < k_lane_chunk; ++i) blocked[i] = 0;
    for (int32_t s = 0; s < a.spheres; ++s) {
        const float cx = a.sphere_center[0][s], cy = a.sphere_center[1][s],
                    cz = a.sphere_center[2][s];
        const float radius = a.sphere_radius[s];
        const float r2 = radius * radius;
        for (int i = 0; i < k_lane_chunk; ++i) {
            const float t = sphere_lane(ox[i] - cx, oy[i] - cy, oz[i] - cz, dx[i], dy[i], dz[i], r2,
                                        distance[i]);
            blocked[i] = t == t ? 1 : blocked[i];
        }
    }
    for (int32_t p = 0; p < a.planes; ++p) {
        const float qx = a.plane_point[0][p], qy = a.plane_point[1][p], qz = a.plane_point[2][p];
        const float mx = a.plane_normal[0][p], my = a.plane_normal[1][p], mz = a.plane_normal[2][p];
        for (int i = 0; i < k_lane_chunk; ++i) {
            const float denominator = mx * dx[i] + my * dy[i] + mz * dz[i];
            const float t =
                ((qx - ox[i]) * mx + (qy - oy[i]) * my + (qz - oz[i]) * mz) / denominator;
            const bool hit = denominator != 0.0f && 0.0f < t && t < distance[i];
            blocked[i] = hit ? 1 : blocked[i];
        }
    }
}

/// shadow_chunk for every chunk of lanes that holds one of the first `count`.
[[maybe_unused]] void shadow_kernel(const PrimaryShadowLight& light, const PrimaryAnalytic& a,
                                    int count, ShadowLanes& lanes) {
    for (int base = 0; base < count; base += k_lane_chunk) shadow_chunk(light, a, lanes, base);
}

}  // namespace
}  // namespace hikari::detail
