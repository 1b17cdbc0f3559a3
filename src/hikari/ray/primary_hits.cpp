#include "hikari/ray/primary_hits.h"

#include <algorithm>
#include <variant>

#include "hikari/ray/primary_hits_kernel.h"
#include "hikari/ray/wide_bvh_packet.h"
#include "hikari/ray/wide_bvh_traversal.h"

namespace hikari {

namespace detail {

void primary_directions_portable(const PrimaryCamera& cam, PrimaryLanes& lanes) {
    directions_kernel(cam, lanes);
}

void primary_analytic_portable(const PrimaryAnalytic& a, int count, PrimaryLanes& lanes) {
    analytic_kernel(a, count, lanes);
}

void primary_shadows_portable(const PrimaryShadowLight& light, const PrimaryAnalytic& casters,
                              int count, ShadowLanes& lanes) {
    shadow_kernel(light, casters, count, lanes);
}

}  // namespace detail

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
    v.planes = static_cast<int32_t>(plane_normal[0].size());
    return v;
}

PrimaryHitTracer::PrimaryHitTracer(const SceneIntersector& intersector, const Scene& scene,
                                   const CameraFrame& frame, SimdLevel level)
    : m_intersector(intersector), m_scene(scene), m_frame(frame), m_level(level) {
    for (const Sphere& s : scene.spheres) {
        m_analytic.add(s);
        if (s.casts_shadow) m_casters.add(s);
    }
    for (const Plane& p : scene.planes) {
        m_analytic.add(p);
        if (p.casts_shadow) m_casters.add(p);
    }
    for (const Light& light : scene.lights) {
        detail::PrimaryShadowLight l{};
        if (const auto* point = std::get_if<PointLight>(&light)) {
            for (int a = 0; a < 3; ++a) l.position[a] = point->position[a];
        } else {
            l.directional = true;
            const Vec3 to_light = -std::get<DirectionalLight>(light).direction;
            for (int a = 0; a < 3; ++a) l.to_light[a] = to_light[a];
        }
        m_lights.push_back(l);
    }
}

void PrimaryHitTracer::trace(int x0, int y0, int width, int height, PrimaryBlock& block) const {
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

    // 1. The camera rays, all lanes at once.
    detail::PrimaryLanes lanes;
    switch (m_level) {
        case SimdLevel::avx512:
            detail::primary_directions_avx512(cam, lanes);
            break;
        case SimdLevel::avx2:
            detail::primary_directions_avx2(cam, lanes);
            break;
        default:
            detail::primary_directions_portable(cam, lanes);
    }
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const int i = y * k_primary_block + x;
            block.rays[i] = {m_frame.eye,
                             {lanes.direction[0][i], lanes.direction[1][i], lanes.direction[2][i]}};
        }

    // 2. Triangles: the block as 4x4 packets through the wide BVH.
    TriangleHit triangle_hits[k_primary_block_rays];
    if (m_scene.triangles.size() > 0) {
        uint8_t* found = block.found;
        intersect_closest_tile(m_intersector.bvh(), block.rays, k_primary_block,
                               static_cast<uint32_t>(width), static_cast<uint32_t>(height),
                               {0.0f, k_infinity}, triangle_hits, found, m_level);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const int i = y * k_primary_block + x;
                if (found[i]) lanes.t[i] = triangle_hits[i].t, lanes.object[i] = 1;
            }
    }
    finish(
        lanes, triangle_hits, height * k_primary_block,
        [&](int i) { return i % k_primary_block < width && i / k_primary_block < height; }, block);
}

void PrimaryHitTracer::trace_rays(int count, PrimaryBlock& block) const {
    detail::PrimaryLanes lanes;
    TriangleHit triangle_hits[k_primary_block_rays];
    const bool triangles = m_scene.triangles.size() > 0;
    for (int i = 0; i < lanes_for(count); ++i) {
        const Ray ray = i < count ? block.rays[i] : Ray{m_frame.eye, {0.0f, 0.0f, 1.0f}};
        for (int a = 0; a < 3; ++a) lanes.origin[a][i] = ray.origin[a];
        for (int a = 0; a < 3; ++a) lanes.direction[a][i] = ray.direction[a];
        lanes.t[i] = k_infinity;
        lanes.object[i] = 0;
        if (triangles && i < count &&
            intersect_closest(m_intersector.bvh(), ray, {0.0f, k_infinity}, triangle_hits[i]))
            lanes.t[i] = triangle_hits[i].t, lanes.object[i] = 1;
    }
    finish(
        lanes, triangle_hits, count, [&](int i) { return i < count; }, block);
}

template <class ValidLane>
void PrimaryHitTracer::finish(detail::PrimaryLanes& lanes, const TriangleHit* triangle_hits,
                              int count, ValidLane valid, PrimaryBlock& block) const {
    const int used = lanes_for(count);
    // 3. Spheres and planes, each against every chunk of lanes that holds rays.
    const detail::PrimaryAnalytic analytic = m_analytic.view();
    switch (m_level) {
        case SimdLevel::avx512:
            detail::primary_analytic_avx512(analytic, count, lanes);
            break;
        case SimdLevel::avx2:
            detail::primary_analytic_avx2(analytic, count, lanes);
            break;
        default:
            detail::primary_analytic_portable(analytic, count, lanes);
    }

    // 4. Each hit described as SceneIntersector::closest describes it.
    const auto spheres = static_cast<int32_t>(m_scene.spheres.size());
    for (int i = 0; i < used; ++i) {
        const int32_t object = valid(i) ? lanes.object[i] : 0;
        block.found[i] = object != 0 ? 1 : 0;
        if (object == 0) continue;
        const HitKind kind = object == 1            ? HitKind::triangle
                             : object < 2 + spheres ? HitKind::sphere
                                                    : HitKind::plane;
        const size_t index = kind == HitKind::sphere  ? static_cast<size_t>(object - 2)
                             : kind == HitKind::plane ? static_cast<size_t>(object - 2 - spheres)
                                                      : 0;
        m_intersector.describe_hit(block.rays[i], lanes.t[i], kind, index, triangle_hits[i],
                                   block.hits[i]);
    }

    std::fill(block.found + used, block.found + k_primary_block_rays, uint8_t{0});

    // 5. The hits' shadow rays, one light at a time against all of them (Boulos et al. 2007 trace
    // shadow rays as packets too: from nearby points toward one light they stay coherent).
    block.shadows_known = m_lights.size() <= k_max_block_lights;
    if (!block.shadows_known) return;
    // The hits packed into the shadow lanes (lane k is block entry hit_of[k]): the kernel's
    // work follows the hits, and a block of sky traces no shadow rays at all.
    detail::ShadowLanes shadow;
    int32_t hit_of[k_primary_block_rays];
    int hits = 0;
    for (int i = 0; i < used; ++i) {
        block.lit[i] = 0;
        if (!block.found[i]) continue;
        const SurfaceHit& hit = block.hits[i];
        // The geometric normal facing the incoming ray, as shade() takes it.
        const Vec3 ng = dot(hit.geometric_normal, block.rays[i].direction) < 0.0f
                            ? hit.geometric_normal
                            : -hit.geometric_normal;
        for (int a = 0; a < 3; ++a)
            shadow.position[a][hits] = hit.position[a], shadow.normal[a][hits] = ng[a];
        hit_of[hits++] = i;
    }
    if (hits == 0) return;
    for (int k = hits; k < lanes_for(hits); ++k)  // the last chunk's spare lanes: harmless rays
        for (int a = 0; a < 3; ++a) shadow.position[a][k] = 0.0f, shadow.normal[a][k] = 0.0f;
    const detail::PrimaryAnalytic casters = m_casters.view();
    const bool triangles = m_scene.triangles.size() > 0;
    for (size_t l = 0; l < m_lights.size(); ++l) {
        switch (m_level) {
            case SimdLevel::avx512:
                detail::primary_shadows_avx512(m_lights[l], casters, hits, shadow);
                break;
            case SimdLevel::avx2:
                detail::primary_shadows_avx2(m_lights[l], casters, hits, shadow);
                break;
            default:
                detail::primary_shadows_portable(m_lights[l], casters, hits, shadow);
        }
        for (int k = 0; k < hits; ++k) {
            if (shadow.blocked[k]) continue;
            const Ray ray{{shadow.origin[0][k], shadow.origin[1][k], shadow.origin[2][k]},
                          {shadow.to_light[0][k], shadow.to_light[1][k], shadow.to_light[2][k]}};
            if (triangles && m_intersector.occluded_by_triangles(ray, {0.0f, shadow.distance[k]}))
                continue;
            block.lit[hit_of[k]] |= static_cast<uint8_t>(1u << l);
        }
    }
}

}  // namespace hikari
