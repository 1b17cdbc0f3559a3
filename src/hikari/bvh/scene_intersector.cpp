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
    hit.t = t;
    hit.position = ray.at(t);
    hit.kind = kind;
    const bool on_triangle = kind == HitKind::triangle;
    hit.index = on_triangle ? triangle.triangle : static_cast<uint32_t>(index);
    hit.bary_u = on_triangle ? triangle.u : 0.0f;
    hit.bary_v = on_triangle ? triangle.v : 0.0f;
    if (kind == HitKind::sphere) {
        const Sphere& s = m_scene.spheres[index];
        hit.geometric_normal = (hit.position - s.center) / s.radius;
        hit.shading_normal = hit.geometric_normal;
        hit.material = s.material;
        hit.id = s.id;
        return;
    }
    if (kind == HitKind::plane) {
        const Plane& p = m_scene.planes[index];
        hit.geometric_normal = p.normal;
        hit.shading_normal = hit.geometric_normal;
        hit.material = p.material;
        hit.id = p.id;
        return;
    }
    const TriangleSet& tris = m_scene.triangles;
    const auto& [i0, i1, i2] = tris.indices[triangle.triangle];
    const Vec3 p0 = tris.positions[i0], p1 = tris.positions[i1], p2 = tris.positions[i2];
    // The lecture's N = (P2 − P1) × (P3 − P2) (Fig 4.5).
    hit.geometric_normal = normalize(cross(p1 - p0, p2 - p1));
    const float w = 1.0f - triangle.u - triangle.v;
    // From the barycentrics rather than origin + t·direction: closer to the surface, which the
    // ray-offset of secondary rays relies on (Wächter & Binder 2019).
    hit.position = p0 * w + p1 * triangle.u + p2 * triangle.v;
    const Vec3 n =
        tris.normals[i0] * w + tris.normals[i1] * triangle.u + tris.normals[i2] * triangle.v;
    const float len2 = dot(n, n);
    hit.shading_normal = len2 > 0.0f ? n / std::sqrt(len2) : hit.geometric_normal;
    hit.material = tris.material[triangle.triangle];
    hit.id = tris.id[triangle.triangle];
}

SurfaceUv SceneIntersector::surface_uv(const SurfaceHit& hit) const {
    if (hit.kind == HitKind::sphere) return sphere_uv(m_scene.spheres[hit.index], hit.position);
    if (hit.kind == HitKind::plane) return plane_uv(m_scene.planes[hit.index], hit.position);
    const TriangleSet& tris = m_scene.triangles;
    if (hit.kind != HitKind::triangle || tris.uvs.empty()) return {};
    const auto& [i0, i1, i2] = tris.indices[hit.index];
    const std::array<Vec2, 3> t{tris.uvs[i0], tris.uvs[i1], tris.uvs[i2]};
    SurfaceUv out =
        triangle_uv_gradients({tris.positions[i0], tris.positions[i1], tris.positions[i2]}, t);
    const float w = 1.0f - hit.bary_u - hit.bary_v;
    out.uv = {t[0].x * w + t[1].x * hit.bary_u + t[2].x * hit.bary_v,
              t[0].y * w + t[1].y * hit.bary_u + t[2].y * hit.bary_v};
    return out;
}

Vec3 SceneIntersector::surface_colour(const SurfaceHit& hit) const {
    const TriangleSet& tris = m_scene.triangles;
    if (hit.kind != HitKind::triangle || tris.colors.empty()) return Vec3(1.0f);
    const auto& [i0, i1, i2] = tris.indices[hit.index];
    const float w = 1.0f - hit.bary_u - hit.bary_v;
    return w * tris.colors[i0] + hit.bary_u * tris.colors[i1] + hit.bary_v * tris.colors[i2];
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
