#include "hikari/ray/primary_hits.h"

#include <algorithm>

#include "hikari/ray/primary_hits_kernel.h"
#include "hikari/ray/wide_bvh_packet.h"

namespace hikari {

namespace detail {

void primary_directions_portable(const PrimaryCamera& cam, PrimaryLanes& lanes) {
    directions_kernel(cam, lanes);
}

void primary_analytic_portable(const PrimaryCamera& cam, const PrimaryAnalytic& a,
                               PrimaryLanes& lanes) {
    analytic_kernel(cam, a, lanes);
}

}  // namespace detail

PrimaryHitTracer::PrimaryHitTracer(const SceneIntersector& intersector, const Scene& scene,
                                   const CameraFrame& frame, SimdLevel level)
    : m_intersector(intersector), m_scene(scene), m_frame(frame), m_level(level) {
    for (const Sphere& s : scene.spheres) {
        for (int a = 0; a < 3; ++a) m_analytic.sphere_center[a].push_back(s.center[a]);
        m_analytic.sphere_radius.push_back(s.radius);
    }
    for (const Plane& p : scene.planes)
        for (int a = 0; a < 3; ++a) {
            m_analytic.plane_point[a].push_back(p.point[a]);
            m_analytic.plane_normal[a].push_back(p.normal[a]);
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
    std::fill(std::begin(lanes.t), std::end(lanes.t), k_infinity);
    std::fill(std::begin(lanes.object), std::end(lanes.object), 0);
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

    // 3. Spheres and planes, each against all lanes.
    detail::PrimaryAnalytic analytic{};
    for (int a = 0; a < 3; ++a) {
        analytic.sphere_center[a] = m_analytic.sphere_center[a].data();
        analytic.plane_point[a] = m_analytic.plane_point[a].data();
        analytic.plane_normal[a] = m_analytic.plane_normal[a].data();
    }
    analytic.sphere_radius = m_analytic.sphere_radius.data();
    analytic.spheres = static_cast<int32_t>(m_scene.spheres.size());
    analytic.planes = static_cast<int32_t>(m_scene.planes.size());
    switch (m_level) {
        case SimdLevel::avx512:
            detail::primary_analytic_avx512(cam, analytic, lanes);
            break;
        case SimdLevel::avx2:
            detail::primary_analytic_avx2(cam, analytic, lanes);
            break;
        default:
            detail::primary_analytic_portable(cam, analytic, lanes);
    }

    // 4. Each hit described as SceneIntersector::closest describes it.
    const auto spheres = static_cast<int32_t>(m_scene.spheres.size());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const int i = y * k_primary_block + x;
            const int32_t object = lanes.object[i];
            block.found[i] = object != 0 ? 1 : 0;
            if (object == 0) continue;
            const HitKind kind = object == 1            ? HitKind::triangle
                                 : object < 2 + spheres ? HitKind::sphere
                                                        : HitKind::plane;
            const size_t index = kind == HitKind::sphere ? static_cast<size_t>(object - 2)
                                 : kind == HitKind::plane
                                     ? static_cast<size_t>(object - 2 - spheres)
                                     : 0;
            m_intersector.describe_hit(block.rays[i], lanes.t[i], kind, index, triangle_hits[i],
                                       block.hits[i]);
        }
}

}  // namespace hikari
