#include "hikari/bvh/scene_intersector.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "hikari/bvh/wide_bvh_builder.h"
#include "hikari/bvh/wide_bvh_traversal.h"
#include "hikari/geometry/intersect.h"

namespace hikari {

SceneIntersector::SceneIntersector(const Scene& scene) : m_scene(scene) {
    const auto start = std::chrono::steady_clock::now();
    const TriangleSet& tris = scene.triangles;
    m_bvh = build_wide_bvh(tris.positions, tris.indices);
    if (tris.casts_shadow.size() == tris.size() &&
        std::find(tris.casts_shadow.begin(), tris.casts_shadow.end(), 0) !=
            tris.casts_shadow.end()) {
        // A second tree over the casters only, so shadow rays never test the others.
        std::vector<std::array<uint32_t, 3>> casters;
        for (size_t i = 0; i < tris.size(); ++i)
            if (tris.casts_shadow[i]) casters.push_back(tris.indices[i]);
        m_shadow_bvh = build_wide_bvh(tris.positions, casters);
        m_all_cast = false;
    }
    m_spheres = build_sphere_bvh(scene.spheres);
    if (std::any_of(scene.spheres.begin(), scene.spheres.end(),
                    [](const Sphere& s) { return !s.casts_shadow; })) {
        m_sphere_casters = build_sphere_bvh(scene.spheres, true);
        m_all_spheres_cast = false;
    }
    m_build_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

bool SceneIntersector::closest(const Ray& ray, Interval range, SurfaceHit& hit) const {
    HitKind kind = HitKind::none;
    TriangleHit triangle_hit;
    if (m_scene.triangles.size() > 0 && intersect_closest(m_bvh, ray, range, triangle_hit)) {
        range.max = triangle_hit.t;
        kind = HitKind::triangle;
    }
    size_t index = 0;
    if (SphereHit sphere_hit; closest_sphere(ray, range, sphere_hit))
        range.max = sphere_hit.t, kind = HitKind::sphere, index = sphere_hit.sphere;
    for (size_t i = 0; i < m_scene.planes.size(); ++i) {
        const Plane& p = m_scene.planes[i];
        const float t = intersect_plane(ray, p.point, p.normal, range);
        if (t == t) range.max = t, kind = HitKind::plane, index = i;
    }
    if (kind == HitKind::none) return false;
    describe_hit(ray, range.max, kind, index, triangle_hit, hit);
    return true;
}

void SceneIntersector::describe_hit(const Ray& ray, float t, HitKind kind, size_t index,
                                    const TriangleHit& triangle, SurfaceHit& hit) const {
    describe_surface_hit(FlatGeometry(m_scene), ray, t, kind, index, triangle, hit);
}

SurfaceUv SceneIntersector::surface_uv(const SurfaceHit& hit) const {
    return surface_uv_of(FlatGeometry(m_scene), hit);
}

Vec3 SceneIntersector::surface_colour(const SurfaceHit& hit) const {
    return surface_colour_of(FlatGeometry(m_scene), hit);
}

bool SceneIntersector::occluded_by_triangles(const Ray& ray, Interval range) const {
    return m_scene.triangles.size() > 0 &&
           intersect_any(m_all_cast ? m_bvh : m_shadow_bvh, ray, range);
}

uint32_t SceneIntersector::occluded_by_triangles(const RayPacket& packet, uint32_t active) const {
    if (m_scene.triangles.size() == 0) return 0;
    return occluded_packet(m_all_cast ? m_bvh : m_shadow_bvh, packet, active);
}

bool SceneIntersector::occluded(const Ray& ray, Interval range) const {
    return occluded_by_triangles(ray, range) || occluded_by_spheres_and_planes(ray, range);
}

bool SceneIntersector::closest_sphere(const Ray& ray, Interval range, SphereHit& hit) const {
    return !m_spheres.empty() && intersect_closest(m_spheres, ray, range, hit);
}

bool SceneIntersector::occluded_by_spheres(const Ray& ray, Interval range) const {
    const SphereBvh& casters = m_all_spheres_cast ? m_spheres : m_sphere_casters;
    return !casters.empty() && intersect_any(casters, ray, range);
}

bool SceneIntersector::occluded_by_spheres_and_planes(const Ray& ray, Interval range) const {
    if (occluded_by_spheres(ray, range)) return true;
    for (const Plane& p : m_scene.planes)
        if (p.casts_shadow && !std::isnan(intersect_plane(ray, p.point, p.normal, range)))
            return true;
    return false;
}

std::shared_ptr<const SceneIntersector> scene_intersector(const Scene& scene, BuildCache* cache,
                                                          bool* built) {
    return cached_or_built<SceneIntersector>(
        cache, &scene, "scene intersector", SceneParts::geometry,
        [&] { return SceneIntersector(scene); }, built);
}

void report_bvh_stats(const SceneIntersector& intersector, RenderStats* stats, bool built) {
    if (!stats) return;
    const WideBvh& bvh = intersector.bvh();
    stats->bvh_triangles = bvh.triangle_count();
    stats->bvh_nodes = bvh.nodes.size();
    stats->bvh_bytes = bvh.memory_bytes();
    stats->bvh_build_us = built ? static_cast<uint64_t>(intersector.build_ms() * 1000.0) : 0;
    stats->bvh_reused = built ? 0 : 1;
    const SphereBvh& spheres = intersector.sphere_bvh();
    stats->bvh_spheres = spheres.sphere_count();
    stats->bvh_sphere_nodes = spheres.tree.nodes.size();
    stats->bvh_sphere_bytes = spheres.memory_bytes();
}

}  // namespace hikari
