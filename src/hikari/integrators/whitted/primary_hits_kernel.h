#pragma once
// The lane loops of the camera-ray front end (primary_hits.h), written once and compiled by
// primary_hits.cpp (baseline x86-64), primary_hits_avx2.cpp and primary_hits_avx512.cpp (after
// their `#pragma GCC target`), which the compiler vectorises across 4, 8 or 16 rays. Each loop
// body is the scalar code's arithmetic (camera_ray, intersect_sphere, intersect_plane in
// geometry/intersect.h) in the same order, with branches turned into selects, so every level rounds
// exactly as the scalar path does (-ffp-contract=off: no FMA). The shadow rays' light sampling
// and origin offset are the generic code the one-ray path runs (shading/lights.h,
// geometry/ray_offset.h), instantiated on packs (core/lanes.h) of the internal-linkage
// `KernelIsa`, so no wider code can leak into shared inline functions: every function here and
// every instantiation on these packs has internal linkage (one copy per including file).

#include <cstdint>

#include "hikari/core/kernel_isa.h"
#include "hikari/core/lanes.h"
#include "hikari/geometry/ray_offset.h"
#include "hikari/integrators/whitted/primary_hits.h"
#include "hikari/shading/lights.h"

namespace hikari::detail {
namespace {

/// camera_ray(frame, x + 0.5, y + 0.5) for every lane: direction = normalize(forward + x right +
/// y up) with x, y the pixel centre on the image plane one unit in front of the eye; no hit yet
/// (t = ∞, object 0). Chunk c is row y0 + c, lane i column x0 + i.
[[maybe_unused]] void directions_kernel(const PrimaryCamera& cam, int chunks, BlockLanes& lanes) {
    const PrimaryCamera c = cam;  // a local copy: the stores below cannot change it
    for (int row = 0; row < chunks; ++row) {
        LaneChunk& chunk = lanes.chunks[row];
        float* __restrict dx = chunk.direction[0];
        float* __restrict dy = chunk.direction[1];
        float* __restrict dz = chunk.direction[2];
        float* __restrict ox = chunk.origin[0];
        float* __restrict oy = chunk.origin[1];
        float* __restrict oz = chunk.origin[2];
        float* __restrict t = chunk.t;
        int32_t* __restrict object = chunk.object;
        const float py = static_cast<float>(c.y0 + row) + 0.5f;
        const float y = (1.0f - 2.0f * py / c.height) * c.tan_half_fov_y;
        for (int i = 0; i < k_lane_chunk; ++i) {
            const float px = static_cast<float>(c.x0 + i) + 0.5f;
            const float x = (2.0f * px / c.width - 1.0f) * c.tan_half_fov_y * c.aspect;
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

/// Whether any of the chunk's 16 rays can hit the sphere (centre c, radius² r2): sphere_lane's
/// first tests, without its square root and division. Where no ray passes, sphere_lane would
/// miss in every lane, so the chunk skips it; most chunks miss most spheres.
[[maybe_unused]] inline bool sphere_may_hit(const float* __restrict ox, const float* __restrict oy,
                                            const float* __restrict oz, const float* __restrict dx,
                                            const float* __restrict dy, const float* __restrict dz,
                                            float cx, float cy, float cz, float r2) {
    int32_t any = 0;
    for (int i = 0; i < k_lane_chunk; ++i) {
        const float fx = ox[i] - cx, fy = oy[i] - cy, fz = oz[i] - cz;
        const float b = -(fx * dx[i] + fy * dy[i] + fz * dz[i]);
        const float qx = fx + dx[i] * b, qy = fy + dy[i] * b, qz = fz + dz[i] * b;
        const float discriminant = r2 - (qx * qx + qy * qy + qz * qz);
        const float c = fx * fx + fy * fy + fz * fz - r2;
        const bool behind = c > 0.0f && b <= 0.0f;
        any |= !(discriminant < 0.0f) && !behind ? 1 : 0;
    }
    return any != 0;
}

/// The nearest of the lanes' triangle hit (already in t / object), the spheres and the planes,
/// tested in SceneIntersector::closest's order: a later primitive wins only when strictly
/// nearer.
inline void analytic_chunk(const PrimaryAnalytic& a, LaneChunk& chunk) {
    const float* __restrict ox = chunk.origin[0];
    const float* __restrict oy = chunk.origin[1];
    const float* __restrict oz = chunk.origin[2];
    const float* __restrict dx = chunk.direction[0];
    const float* __restrict dy = chunk.direction[1];
    const float* __restrict dz = chunk.direction[2];
    float* __restrict t_max = chunk.t;
    int32_t* __restrict object = chunk.object;
    const int32_t spheres = a.spheres, planes = a.planes;

    for (int32_t s = 0; s < spheres; ++s) {
        const float cx = a.sphere_center[0][s], cy = a.sphere_center[1][s],
                    cz = a.sphere_center[2][s];
        const float radius = a.sphere_radius[s];
        const float r2 = radius * radius;
        if (!sphere_may_hit(ox, oy, oz, dx, dy, dz, cx, cy, cz, r2)) continue;
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
            object[i] = hit ? 2 + a.sphere_codes + p : object[i];
        }
    }
}

/// analytic_chunk for the first `chunks` chunks.
[[maybe_unused]] void analytic_kernel(const PrimaryAnalytic& a, int chunks, BlockLanes& lanes) {
    for (int c = 0; c < chunks; ++c) analytic_chunk(a, lanes.chunks[c]);
}

/// The distinct values of a chunk's lanes into `out`, in order of first appearance; returns
/// how many. One vector compare answers the common chunk of a single value.
[[maybe_unused]] inline int32_t distinct_values(const int32_t* __restrict values,
                                                int32_t* __restrict out) {
    const int32_t first = values[0];
    int32_t same = 1;
    for (int i = 0; i < k_lane_chunk; ++i) same &= values[i] == first ? 1 : 0;
    out[0] = first;
    if (same != 0) return 1;
    int32_t count = 1;
    for (int i = 1; i < k_lane_chunk; ++i) {
        bool seen = false;
        for (int32_t k = 0; k < count; ++k) seen = seen || out[k] == values[i];
        if (!seen) out[count++] = values[i];
    }
    return count;
}

/// SceneIntersector::describe_hit for sphere and plane hits: position = origin + direction t,
/// a sphere's normal (position - centre) (1 / radius), a plane's its own. Each object present in
/// the chunk (usually one or two) has its values broadcast into its lanes: g++ vectorises such
/// selects but emulates table lookups one lane at a time.
inline void describe_chunk(const PrimaryObjects& o, LaneChunk& chunk) {
    const float* __restrict ox = chunk.origin[0];
    const float* __restrict oy = chunk.origin[1];
    const float* __restrict oz = chunk.origin[2];
    const float* __restrict dx = chunk.direction[0];
    const float* __restrict dy = chunk.direction[1];
    const float* __restrict dz = chunk.direction[2];
    const float* __restrict t = chunk.t;
    const int32_t* __restrict object = chunk.object;
    int32_t* __restrict active = chunk.active;
    float* __restrict px = chunk.position[0];
    float* __restrict py = chunk.position[1];
    float* __restrict pz = chunk.position[2];
    float* __restrict gx = chunk.geometric_normal[0];
    float* __restrict gy = chunk.geometric_normal[1];
    float* __restrict gz = chunk.geometric_normal[2];
    float* __restrict sx = chunk.shading_normal[0];
    float* __restrict sy = chunk.shading_normal[1];
    float* __restrict sz = chunk.shading_normal[2];
    int32_t* __restrict material = chunk.material;
    uint32_t* __restrict id = chunk.id;
    for (int i = 0; i < k_lane_chunk; ++i) {
        const bool hit = object[i] != 0;
        active[i] = hit ? 1 : 0;
        px[i] = hit ? ox[i] + dx[i] * t[i] : 0.0f;
        py[i] = hit ? oy[i] + dy[i] * t[i] : 0.0f;
        pz[i] = hit ? oz[i] + dz[i] * t[i] : 0.0f;
    }
    int32_t present[k_lane_chunk];
    const int32_t present_count = distinct_values(object, present);
    for (int32_t k = 0; k < present_count; ++k) {
        const int32_t m = present[k];
        const bool sphere = o.is_sphere[m] != 0;
        const float cx = o.center[0][m], cy = o.center[1][m], cz = o.center[2][m];
        const float inverse_radius = o.inverse_radius[m];
        const float nx = o.normal[0][m], ny = o.normal[1][m], nz = o.normal[2][m];
        const int32_t object_material = o.material[m];
        const uint32_t object_id = o.id[m];
        // The first object's values go to every lane (the later ones overwrite theirs), which
        // saves reading the outputs.
        if (k == 0) {
            for (int i = 0; i < k_lane_chunk; ++i) {
                const float qx = (px[i] - cx) * inverse_radius, qy = (py[i] - cy) * inverse_radius,
                            qz = (pz[i] - cz) * inverse_radius;
                gx[i] = sphere ? qx : nx, gy[i] = sphere ? qy : ny, gz[i] = sphere ? qz : nz;
                sx[i] = gx[i], sy[i] = gy[i], sz[i] = gz[i];
                material[i] = object_material;
                id[i] = object_id;
            }
            continue;
        }
        for (int i = 0; i < k_lane_chunk; ++i) {
            const bool mine = object[i] == m;
            const float qx = (px[i] - cx) * inverse_radius, qy = (py[i] - cy) * inverse_radius,
                        qz = (pz[i] - cz) * inverse_radius;
            const float ax = sphere ? qx : nx, ay = sphere ? qy : ny, az = sphere ? qz : nz;
            gx[i] = mine ? ax : gx[i], gy[i] = mine ? ay : gy[i], gz[i] = mine ? az : gz[i];
            sx[i] = mine ? ax : sx[i], sy[i] = mine ? ay : sy[i], sz[i] = mine ? az : sz[i];
            material[i] = mine ? object_material : material[i];
            id[i] = mine ? object_id : id[i];
        }
    }
}

/// describe_chunk for the first `chunks` chunks.
[[maybe_unused]] void describe_kernel(const PrimaryObjects& o, int chunks, BlockLanes& lanes) {
    for (int c = 0; c < chunks; ++c) describe_chunk(o, lanes.chunks[c]);
}

/// SceneIntersector::occluded's sphere and plane tests for the chunk's shadow rays (origin,
/// direction, distance): blocked[i] = 1 where a casting sphere or plane is in the way.
inline void block_by_spheres_and_planes(const PrimaryAnalytic& a, LaneChunk& chunk) {
    // Only `blocked` is written, and as int32_t it cannot alias the float arrays read.
    const float(&o)[3][k_lane_chunk] = chunk.shadow_origin;
    const float(&d)[3][k_lane_chunk] = chunk.shadow_direction;
    const float* __restrict distance = chunk.shadow_distance;
    int32_t* __restrict blocked = chunk.blocked;
    for (int i = 0; i < k_lane_chunk; ++i) blocked[i] = 0;
    for (int32_t s = 0; s < a.spheres; ++s) {
        const float cx = a.sphere_center[0][s], cy = a.sphere_center[1][s],
                    cz = a.sphere_center[2][s];
        const float radius = a.sphere_radius[s];
        const float r2 = radius * radius;
        if (!sphere_may_hit(o[0], o[1], o[2], d[0], d[1], d[2], cx, cy, cz, r2)) continue;
        for (int i = 0; i < k_lane_chunk; ++i) {
            const float t = sphere_lane(o[0][i] - cx, o[1][i] - cy, o[2][i] - cz, d[0][i], d[1][i],
                                        d[2][i], r2, distance[i]);
            blocked[i] = t == t ? 1 : blocked[i];
        }
    }
    for (int32_t p = 0; p < a.planes; ++p) {
        const float qx = a.plane_point[0][p], qy = a.plane_point[1][p], qz = a.plane_point[2][p];
        const float mx = a.plane_normal[0][p], my = a.plane_normal[1][p], mz = a.plane_normal[2][p];
        for (int i = 0; i < k_lane_chunk; ++i) {
            const float denominator = mx * d[0][i] + my * d[1][i] + mz * d[2][i];
            const float t =
                ((qx - o[0][i]) * mx + (qy - o[1][i]) * my + (qz - o[2][i]) * mz) / denominator;
            const bool hit = denominator != 0.0f && 0.0f < t && t < distance[i];
            blocked[i] = hit ? 1 : blocked[i];
        }
    }
}

/// Shadow rays from the lanes' hit points toward one light, as the one-ray shading casts them
/// (integrators/whitted/whitted_surface.h): from offset_ray_origin(position, the geometric
/// normal turned toward the camera ray) along shading/lights.h's direction toward the light, up
/// to its distance; then the casting spheres and planes tested, per lane. Lanes
/// without a hit (zero position and normal) get harmless finite rays.
inline void shadow_chunk(const Light& light, const PrimaryAnalytic& a, LaneChunk& chunk) {
    for (int first = 0; first < k_lane_chunk; first += KernelIsa::k_width) {
        const Vec3T<LaneF> p = load_lanes<KernelIsa>(chunk.position, first);
        const Vec3T<LaneF> g = load_lanes<KernelIsa>(chunk.geometric_normal, first);
        const Vec3T<LaneF> d = load_lanes<KernelIsa>(chunk.direction, first);
        const LaneMask<KernelIsa> facing = dot(g, d) < 0.0f;
        store_lanes<KernelIsa>(offset_ray_origin(p, select(facing, g, -g)), chunk.shadow_origin,
                               first);
        const LightSampleT<LaneF> toward = sample_light<LaneF>(light, p);
        store_lanes<KernelIsa>(toward.to_light, chunk.shadow_direction, first);
        toward.distance.store(chunk.shadow_distance + first);
    }

    block_by_spheres_and_planes(a, chunk);
}

/// shadow_chunk for each of the first `chunks` chunks that holds a hit.
[[maybe_unused]] void shadow_kernel(const Light& light, const PrimaryAnalytic& a, int chunks,
                                    BlockLanes& lanes) {
    for (int c = 0; c < chunks; ++c) {
        LaneChunk& chunk = lanes.chunks[c];
        if (any_active(chunk)) shadow_chunk(light, a, chunk);
    }
}

}  // namespace
}  // namespace hikari::detail
