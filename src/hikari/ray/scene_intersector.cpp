#include "hikari/ray/scene_intersector.h"

#include <cmath>

#include "hikari/ray/intersect.h"

namespace hikari {

SceneIntersector::SceneIntersector(const Scene& scene) : m_scene(scene) {}

bool SceneIntersector::closest(const Ray& ray, Interval range, SurfaceHit& hit) const {
    enum class Kind { none, sphere, plane } kind = Kind::none;
    size_t index = 0;
    for (size_t i = 0; i < m_scene.spheres.size(); ++i) {
        const Sphere& s = m_scene.spheres[i];
        const float t = intersect_sphere(ray, s.center, s.radius, range);
        if (t == t) range.max = t, kind = Kind::sphere, index = i;  // t == t: not NaN
    }
    for (size_t i = 0; i < m_scene.planes.size(); ++i) {
        const Plane& p = m_scene.planes[i];
        const float t = intersect_plane(ray, p.point, p.normal, range);
        if (t == t) range.max = t, kind = Kind::plane, index = i;
    }
    if (kind == Kind::none) return false;
    hit.t = range.max;
    hit.position = ray.at(hit.t);
    if (kind == Kind::sphere) {
        const Sphere& s = m_scene.spheres[index];
        hit.geometric_normal = (hit.position - s.center) / s.radius;
        hit.material = s.material;
        hit.id = s.id;
    } else {
        const Plane& p = m_scene.planes[index];
        hit.geometric_normal = p.normal;
        hit.material = p.material;
        hit.id = p.id;
    }
    hit.shading_normal = hit.geometric_normal;
    return true;
}

bool SceneIntersector::occluded(const Ray& ray, Interval range) const {
    for (const Sphere& s : m_scene.spheres)
        if (!std::isnan(intersect_sphere(ray, s.center, s.radius, range))) return true;
    for (const Plane& p : m_scene.planes)
        if (!std::isnan(intersect_plane(ray, p.point, p.normal, range))) return true;
    return false;
}

}  // namespace hikari
