#include "hikari/integrators/whitted/primary_hits.h"

#include <algorithm>
#include <variant>

#include "hikari/bvh/wide_bvh_packet.h"
#include "hikari/bvh/wide_bvh_traversal.h"
#include "hikari/integrators/whitted/primary_hits_kernel.h"

namespace hikari {

namespace detail {

void primary_directions_portable(const PrimaryCamera& cam, int chunks, BlockLanes& lanes) {
    directions_kernel(cam, chunks, lanes);
}

void primary_analytic_portable(const PrimaryAnalytic& a, int chunks, BlockLanes& lanes) {
    analytic_kernel(a, chunks, lanes);
}

void primary_describe_portable(const PrimaryObjects& o, int chunks, BlockLanes& lanes) {
    describe_kernel(o, chunks, lanes);
}

void primary_shadows_portable(const Light& light, const PrimaryAnalytic& casters, int chunks,
                              BlockLanes& lanes) {
    shadow_kernel(light, casters, chunks, lanes);
}

}  // namespace detail

Ray PrimaryBlock::ray(int k) const {
    const detail::LaneChunk& c = lanes.chunk(k);
    const int j = detail::lane_in_chunk(k);
    return {{c.origin[0][j], c.origin[1][j], c.origin[2][j]},
            {c.direction[0][j], c.direction[1][j], c.direction[2][j]}};
}

SurfaceHit PrimaryBlock::hit(int k) const {
    const detail::LaneChunk& c = lanes.chunk(k);
    const int j = detail::lane_in_chunk(k);
    SurfaceHit hit;
    hit.t = c.t[j];
    hit.position = {c.position[0][j], c.position[1][j], c.position[2][j]};
    hit.geometric_normal = {c.geometric_normal[0][j], c.geometric_normal[1][j],
                            c.geometric_normal[2][j]};
    hit.shading_normal = {c.shading_normal[0][j], c.shading_normal[1][j], c.shading_normal[2][j]};
    hit.material = static_cast<uint32_t>(c.material[j]);
    hit.id = c.id[j];
    // Object codes: 1 triangle, 2 + i sphere i, 2 + spheres + i plane i.
    const int32_t object = c.object[j];
    if (object == 1) {
        hit.kind = HitKind::triangle;
        hit.index = c.triangle[j];
        hit.bary_u = c.bary[0][j], hit.bary_v = c.bary[1][j];
    } else if (object >= 2) {
        const bool sphere = object - 2 < spheres;
        hit.kind = sphere ? HitKind::sphere : HitKind::plane;
        hit.index = static_cast<uint32_t>(sphere ? object - 2 : object - 2 - spheres);
    }
    return hit;
}

void PrimaryHitTracer::Analytic::add(const Sphere& s) {
    for (int a = 0; a < 3; ++a) sphere_center[a].push_back(s.center[a]);
    sphere_radius.push_back(s.radius);
}

void PrimaryHitTracer::Analytic::add(const Plane& p) {
    for (int a = 0; a < 3; ++a) {
        plane_point[a].push_back(p.point[a]);
        plane_normal[a].push_back(p.normal[a]);
    }
}

detail::PrimaryAnalytic PrimaryHitTracer::Analytic::view() const {
    detail::PrimaryAnalytic v{};
    for (int a = 0; a < 3; ++a) {
        v.sphere_center[a] = sphere_center[a].data();
        v.plane_point[a] = plane_point[a].data();
        v.plane_normal[a] = plane_normal[a].data();
    }
    v.sphere_radius = sphere_radius.data();
    v.spheres = static_cast<int32_t>(sphere_radius.size());
    v.sphere_codes = sphere_codes;
    v.planes = static_cast<int32_t>(plane_normal[0].size());
    return v;
}

void PrimaryHitTracer::Objects::add(int32_t sphere, Vec3 c, float inverse_r, Vec3 n,
                                    uint32_t object_material, PrimitiveId object_id) {
    is_sphere.push_back(sphere);
    for (int a = 0; a < 3; ++a) center[a].push_back(c[a]), normal[a].push_back(n[a]);
    inverse_radius.push_back(inverse_r);
    material.push_back(static_cast<int32_t>(object_material));
    id.push_back(object_id);
}

detail::PrimaryObjects PrimaryHitTracer::Objects::view() const {
    detail::PrimaryObjects v{};
    v.is_sphere = is_sphere.data();
    for (int a = 0; a < 3; ++a) v.center[a] = center[a].data(), v.normal[a] = normal[a].data();
    v.inverse_radius = inverse_radius.data();
    v.material = material.data();
    v.id = id.data();
    return v;
}

PrimaryHitTracer::PrimaryHitTracer(const SceneIntersector& intersector, const Scene& scene,
                                   const CameraFrame& frame, SimdLevel level)
    : m_intersector(intersector), m_scene(scene), m_frame(frame), m_level(level) {
    // Past a few dozen spheres one BVH walk per ray costs less than every sphere per block of
    // rays (an estimate, not tuned: a few ns per sphere and 16 rays in the lanes against some
    // 100 ns per walk); both give the same answers.
    constexpr size_t k_lane_sphere_limit = 64;
    m_spheres_in_lanes = scene.spheres.size() <= k_lane_sphere_limit;
    m_casts_shadows = casts_any_shadow(scene);
    m_analytic.sphere_codes = m_casters.sphere_codes = static_cast<int32_t>(scene.spheres.size());
    // Object codes 0 (no hit) and 1 (triangle) first, then spheres, then planes. A sphere's
    // normal is (p - centre) / radius, which Vec3's operator/ computes as (p - centre) * (1 /
    // radius).
    for (int none = 0; none < 2; ++none) m_objects.add(0, Vec3(0.0f), 0.0f, Vec3(0.0f), 0, 0);
    for (const Sphere& s : scene.spheres) {
        if (m_spheres_in_lanes) m_analytic.add(s);
        if (m_spheres_in_lanes && s.casts_shadow) m_casters.add(s);
        m_objects.add(1, s.center, 1.0f / s.radius, Vec3(0.0f), s.material, s.id);
    }
    for (const Plane& p : scene.planes) {
        m_analytic.add(p);
        if (p.casts_shadow) m_casters.add(p);
        m_objects.add(0, Vec3(0.0f), 0.0f, p.normal, p.material, p.id);
    }
}

void PrimaryHitTracer::trace(int x0, int y0, int width, int height, PrimaryBlock& block) const {
    if (m_frame.orthographic) {
        // Parallel rays from many origins: the lanes' origins are the rays' own, one ray at a
        // time through the BVH (the 4x4 packets below share the eye as their origin). Rows stay
        // k_primary_block rays long, the block's layout; the columns past the image hold no ray.
        Ray rays[k_primary_block_rays];
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < k_primary_block; ++x)
                rays[y * k_primary_block + x] = camera_ray(
                    m_frame, static_cast<float>(x0 + x) + 0.5f, static_cast<float>(y0 + y) + 0.5f);
        trace_rays(rays, height * k_primary_block, block);
        if (width < k_primary_block)
            for (int y = 0; y < height; ++y)
                std::fill(block.lanes.chunks[y].object + width,
                          block.lanes.chunks[y].object + k_lane_chunk, 0);
        return;
    }
    detail::PrimaryCamera cam{};
    for (int a = 0; a < 3; ++a) {
        cam.eye[a] = m_frame.eye[a];
        cam.right[a] = m_frame.right[a];
        cam.up[a] = m_frame.up[a];
        cam.forward[a] = m_frame.forward[a];
    }
    cam.tan_half_fov_y = m_frame.tan_half_fov_y;
    cam.aspect = m_frame.aspect;
    cam.width = static_cast<float>(m_frame.width);
    cam.height = static_cast<float>(m_frame.height);
    cam.x0 = x0;
    cam.y0 = y0;

    // 1. The camera rays, one chunk per row.
    block.chunks = height;
    simd_pick(m_level, detail::primary_directions_portable, detail::primary_directions_avx2,
              detail::primary_directions_avx512)(cam, height, block.lanes);

    // 2. Triangles: the block as 4x4 packets through the wide BVH.
    TriangleHit triangle_hits[k_primary_block_rays];
    if (m_scene.triangles.size() > 0) {
        Ray rays[k_primary_block_rays];
        uint8_t found[k_primary_block_rays];
        for (int k = 0; k < height * k_primary_block; ++k) rays[k] = block.ray(k);
        intersect_closest_tile(m_intersector.bvh(), rays, k_primary_block,
                               static_cast<uint32_t>(width), static_cast<uint32_t>(height),
                               {0.0f, k_infinity}, triangle_hits, found, m_level);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const int k = y * k_primary_block + x;
                if (!found[k]) continue;
                detail::LaneChunk& chunk = block.lanes.chunks[y];
                chunk.t[x] = triangle_hits[k].t, chunk.object[x] = 1;
            }
    }

    // 3. Spheres and planes; pixels right of the image's edge hold no ray of the block.
    if (!m_spheres_in_lanes)
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) find_spheres(y * k_primary_block + x, block);
    simd_pick(m_level, detail::primary_analytic_portable, detail::primary_analytic_avx2,
              detail::primary_analytic_avx512)(m_analytic.view(), height, block.lanes);
    if (width < k_primary_block)
        for (int y = 0; y < height; ++y)
            std::fill(block.lanes.chunks[y].object + width,
                      block.lanes.chunks[y].object + k_lane_chunk, 0);
    finish(triangle_hits, block);
}

void PrimaryHitTracer::trace_rays(const Ray* rays, int count, PrimaryBlock& block) const {
    TriangleHit triangle_hits[k_primary_block_rays];
    const bool triangles = m_scene.triangles.size() > 0;
    const int used = lanes_for(count);
    block.chunks = used / k_lane_chunk;
    for (int k = 0; k < used; ++k) {
        // The last chunk's spare lanes: a harmless finite ray, its hit dropped below.
        const Ray ray = k < count ? rays[k] : Ray{m_frame.eye, {0.0f, 0.0f, 1.0f}};
        detail::LaneChunk& chunk = block.lanes.chunk(k);
        const int j = detail::lane_in_chunk(k);
        for (int a = 0; a < 3; ++a) {
            chunk.origin[a][j] = ray.origin[a];
            chunk.direction[a][j] = ray.direction[a];
        }
        chunk.t[j] = k_infinity;
        chunk.object[j] = 0;
        if (triangles && k < count &&
            intersect_closest(m_intersector.bvh(), ray, {0.0f, k_infinity}, triangle_hits[k]))
            chunk.t[j] = triangle_hits[k].t, chunk.object[j] = 1;
        if (!m_spheres_in_lanes && k < count) find_spheres(k, block);
    }
    simd_pick(m_level, detail::primary_analytic_portable, detail::primary_analytic_avx2,
              detail::primary_analytic_avx512)(m_analytic.view(), block.chunks, block.lanes);
    for (int k = count; k < used; ++k) block.lanes.chunk(k).object[detail::lane_in_chunk(k)] = 0;
    finish(triangle_hits, block);
}

void PrimaryHitTracer::find_spheres(int k, PrimaryBlock& block) const {
    detail::LaneChunk& chunk = block.lanes.chunk(k);
    const int j = detail::lane_in_chunk(k);
    // SceneIntersector::closest's sphere step, on the lane's range (0, nearest triangle).
    if (SphereHit hit; m_intersector.closest_sphere(block.ray(k), {0.0f, chunk.t[j]}, hit))
        chunk.t[j] = hit.t, chunk.object[j] = 2 + static_cast<int32_t>(hit.sphere);
}

bool PrimaryHitTracer::sphere_blocks_shadow(const detail::LaneChunk& chunk, int j) const {
    const Ray ray{
        {chunk.shadow_origin[0][j], chunk.shadow_origin[1][j], chunk.shadow_origin[2][j]},
        {chunk.shadow_direction[0][j], chunk.shadow_direction[1][j], chunk.shadow_direction[2][j]}};
    return m_intersector.occluded_by_spheres(ray, {0.0f, chunk.shadow_distance[j]});
}

void PrimaryHitTracer::finish(const TriangleHit* triangle_hits, PrimaryBlock& block) const {
    const int chunks = block.chunks;
    detail::BlockLanes& lanes = block.lanes;
    // 4. Each hit described as SceneIntersector::closest describes it: spheres and planes in the
    // lanes, triangles one at a time.
    simd_pick(m_level, detail::primary_describe_portable, detail::primary_describe_avx2,
              detail::primary_describe_avx512)(m_objects.view(), chunks, lanes);
    const bool triangles = m_scene.triangles.size() > 0;
    if (triangles)
        for (int k = 0; k < chunks * k_lane_chunk; ++k) {
            detail::LaneChunk& chunk = lanes.chunk(k);
            const int j = detail::lane_in_chunk(k);
            if (chunk.object[j] != 1) continue;
            SurfaceHit hit;
            m_intersector.describe_hit(block.ray(k), chunk.t[j], HitKind::triangle, 0,
                                       triangle_hits[k], hit);
            for (int a = 0; a < 3; ++a) {
                chunk.position[a][j] = hit.position[a];
                chunk.geometric_normal[a][j] = hit.geometric_normal[a];
                chunk.shading_normal[a][j] = hit.shading_normal[a];
            }
            chunk.material[j] = static_cast<int32_t>(hit.material);
            chunk.id[j] = hit.id;
            chunk.triangle[j] = hit.index;
            chunk.bary[0][j] = hit.bary_u, chunk.bary[1][j] = hit.bary_v;
        }
    block.spheres = static_cast<int32_t>(m_scene.spheres.size());

    // 5. The hits' shadow rays, one light at a time against all of them (Boulos et al. 2007 trace
    // shadow rays as packets too: from nearby points toward one light they stay coherent).
    // Area and environment lights take many shadow rays per hit: the one-ray code casts them.
    block.shadows_known = m_scene.lights.size() <= k_max_block_lights &&
                          std::all_of(m_scene.lights.begin(), m_scene.lights.end(), is_delta_light);
    if (!block.shadows_known) return;
    if (!m_casts_shadows) {  // nothing can block a shadow ray: every light is seen, none traced
        for (int c = 0; c < chunks; ++c) std::fill_n(lanes.chunks[c].lit, k_lane_chunk, -1);
        return;
    }
    for (int c = 0; c < chunks; ++c) std::fill_n(lanes.chunks[c].lit, k_lane_chunk, 0);
    const auto shadows = simd_pick(m_level, detail::primary_shadows_portable,
                                   detail::primary_shadows_avx2, detail::primary_shadows_avx512);
    const detail::PrimaryAnalytic casters = m_casters.view();
    static_assert(k_lane_chunk == int(k_packet_size));
    RayPacket packet;
    std::fill_n(packet.t_min, k_packet_size, 0.0f);
    for (size_t l = 0; l < m_scene.lights.size(); ++l) {
        shadows(m_scene.lights[l], casters, chunks, lanes);
        const auto bit = static_cast<int32_t>(1u << l);
        for (int c = 0; c < chunks; ++c) {
            detail::LaneChunk& chunk = lanes.chunks[c];
            if (!any_active(chunk)) continue;  // the kernel skipped it
            uint32_t open = 0;                 // lanes whose shadow ray no sphere or plane blocks
            for (int j = 0; j < k_lane_chunk; ++j)
                if (chunk.active[j] && !chunk.blocked[j]) open |= 1u << j;
            if (open != 0 && triangles) {
                // A row of hits toward one light: coherent, so traced as one packet.
                for (int a = 0; a < 3; ++a) {
                    std::copy_n(chunk.shadow_origin[a], k_lane_chunk, packet.origin[a]);
                    std::copy_n(chunk.shadow_direction[a], k_lane_chunk, packet.direction[a]);
                }
                std::copy_n(chunk.shadow_distance, k_lane_chunk, packet.t_max);
                open &= ~m_intersector.occluded_by_triangles(packet, open);
            }
            if (!m_spheres_in_lanes)
                for (int j = 0; j < k_lane_chunk; ++j)
                    if ((open & (1u << j)) && sphere_blocks_shadow(chunk, j)) open &= ~(1u << j);
            for (int j = 0; j < k_lane_chunk; ++j)
                if (open & (1u << j)) chunk.lit[j] |= bit;
        }
    }
}

}  // namespace hikari
