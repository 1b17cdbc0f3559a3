#include "hikari/integrators/path/emitters.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "hikari/core/aabb.h"
#include "hikari/core/color.h"
#include "hikari/shading/bsdf/lambert.h"
#include "hikari/shading/lights.h"

namespace hikari {

namespace {

constexpr float k_pi = std::numbers::pi_v<float>;
constexpr float k_far = std::numeric_limits<float>::infinity();

/// The radius of a sphere about the scene's bounded geometry and camera (lights at infinity
/// send power through its disc).
float scene_radius(const Scene& scene) {
    Aabb box = Aabb::from_point(scene.camera.eye);
    for (const Vec3& p : scene.triangles.positions) box.extend(p);
    for (const Sphere& s : scene.spheres) {
        box.extend(s.center - Vec3(s.radius));
        box.extend(s.center + Vec3(s.radius));
    }
    for (const Light& light : scene.lights)
        if (const std::optional<Vec3> p = light_position(light)) box.extend(*p);
    return std::max(0.5f * length(box.max - box.min), 1e-3f);
}

/// The mean radiance of an environment light over all directions.
float mean_luminance(const EnvironmentLight& env) {
    if (!env.map) return luminance(env.radiance);
    const Image& image = env.map->image();
    double sum = 0.0, weight = 0.0;
    for (int y = 0; y < image.height; ++y) {
        const double sin_theta = std::sin(k_pi * (y + 0.5) / image.height);
        for (int x = 0; x < image.width; ++x) {
            sum += sin_theta * luminance(image.at(x, y));
            weight += sin_theta;
        }
    }
    return weight > 0.0 ? luminance(env.radiance) * static_cast<float>(sum / weight) : 0.0f;
}

}  // namespace

EmitterTable::EmitterTable(const Scene& scene) : m_scene(scene) {
    const float radius = scene_radius(scene);
    double total = 0.0;
    std::vector<double> powers;
    const auto add = [&](const Entry& entry, double power) -> int32_t {
        if (!(power > 0.0) || !std::isfinite(power)) return -1;
        m_entries.push_back(entry);
        powers.push_back(power);
        total += power;
        m_cdf.push_back(total);
        return static_cast<int32_t>(m_entries.size() - 1);
    };
    // An emitter with no surface (a light at a point or at infinity).
    const auto only = [](EmitterKind kind, uint32_t index) {
        Entry e;
        e.kind = kind;
        e.index = index;
        return e;
    };
    // A parallelogram or triangle spanned by two edges from a corner.
    const auto surface = [&only](EmitterKind kind, uint32_t index, Vec3 corner, Vec3 edge1,
                                 Vec3 edge2, Vec3 radiance, bool two_sided) {
        Entry e = only(kind, index);
        e.corner = corner, e.edge1 = edge1, e.edge2 = edge2;
        const Vec3 n = cross(edge1, edge2);
        const float len = length(n);
        e.front = len > 0.0f ? n / len : Vec3(0.0f);
        e.area = kind == EmitterKind::triangle ? 0.5f * len : len;
        e.radiance = radiance;
        e.two_sided = two_sided;
        return e;
    };
    // Powers: what each emits in all, Φ = π·L·A for a one-sided face, 4π·I for a point light;
    // lights at infinity by what crosses the scene's disc.
    const TriangleSet& tris = scene.triangles;
    for (uint32_t i = 0; i < tris.size(); ++i) {
        const Vec3 emission = scene.materials[tris.material[i]].emission;
        if (max_component(emission) <= 0.0f) continue;
        if (m_triangle_entry.empty()) m_triangle_entry.assign(tris.size(), -1);
        const auto& [a, b, c] = tris.indices[i];
        const Vec3 pa = tris.positions[a];
        const Entry e = surface(EmitterKind::triangle, i, pa, tris.positions[b] - pa,
                                tris.positions[c] - pa, emission, false);
        m_triangle_entry[i] = add(e, k_pi * luminance(emission) * e.area);
    }
    m_light_entry.assign(scene.lights.size(), -1);
    for (uint32_t l = 0; l < scene.lights.size(); ++l) {
        const Light& light = scene.lights[l];
        if (const auto* area = std::get_if<AreaLight>(&light)) {
            const Entry e = surface(EmitterKind::area, l, area->corner, area->edge1, area->edge2,
                                    area->radiance, area->two_sided);
            m_light_entry[l] =
                add(e, (area->two_sided ? 2.0 : 1.0) * k_pi * luminance(area->radiance) * e.area);
        } else if (const auto* env = std::get_if<EnvironmentLight>(&light)) {
            m_light_entry[l] = m_environment_entry =
                add(only(EmitterKind::environment, l),
                    k_pi * k_pi * radius * radius * mean_luminance(*env));
        } else if (const auto* point = std::get_if<PointLight>(&light)) {
            m_light_entry[l] =
                add(only(EmitterKind::point, l), 4.0 * k_pi * luminance(point->intensity));
        } else if (const auto* sun = std::get_if<DirectionalLight>(&light)) {
            m_light_entry[l] = add(only(EmitterKind::directional, l),
                                   k_pi * radius * radius * luminance(sun->intensity));
        }
    }
    for (size_t i = 0; i < m_entries.size(); ++i)
        m_entries[i].choice = static_cast<float>(powers[i] / total);
}

float EmitterTable::surface_pdf(const Entry& entry, Vec3 dir, float t) {
    float cos_y = -dot(entry.front, dir);
    if (entry.two_sided) cos_y = std::abs(cos_y);
    if (!(cos_y > 0.0f) || !(entry.area > 0.0f)) return 0.0f;
    return entry.choice * t * t / (entry.area * cos_y);
}

EmitterSample EmitterTable::sample(Vec3 p, Vec3 n, float u_choice, Vec2 u) const {
    EmitterSample s;
    if (m_cdf.empty()) return s;
    const double target = static_cast<double>(u_choice) * m_cdf.back();
    const size_t chosen = std::min<size_t>(
        static_cast<size_t>(std::upper_bound(m_cdf.begin(), m_cdf.end(), target) - m_cdf.begin()),
        m_cdf.size() - 1);
    const Entry& e = m_entries[chosen];
    switch (e.kind) {
        case EmitterKind::triangle:
        case EmitterKind::area: {
            // Uniform over the area; a triangle folds the square by the square root (Turk 1990).
            Vec3 y;
            if (e.kind == EmitterKind::triangle) {
                const float su = std::sqrt(u.x);
                y = e.corner + (su * (1.0f - u.y)) * e.edge1 + (su * u.y) * e.edge2;
            } else {
                y = e.corner + u.x * e.edge1 + u.y * e.edge2;
            }
            const Vec3 d = y - p;
            const float r2 = dot(d, d);
            if (!(r2 > 0.0f)) break;
            s.distance = std::sqrt(r2);
            s.to_light = d / s.distance;
            s.pdf = surface_pdf(e, s.to_light, s.distance);
            if (s.pdf > 0.0f) s.radiance = e.radiance;
            break;
        }
        case EmitterKind::environment: {
            const EnvironmentLight& env = std::get<EnvironmentLight>(m_scene.lights[e.index]);
            s.distance = k_far;
            if (env.map) {
                const EnvironmentDirection d = env.map->sample(u);
                s.to_light = d.direction;
                if (!(d.pdf > 0.0f)) break;
                s.radiance = env.radiance * d.radiance;
                s.pdf = e.choice * d.pdf;
            } else {
                s.to_light = cosine_hemisphere_direction(n, u);
                const float pdf = cosine_hemisphere_pdf(dot(n, s.to_light));
                if (!(pdf > 0.0f)) break;
                s.radiance = env.radiance;
                s.pdf = e.choice * pdf;
            }
            break;
        }
        case EmitterKind::point:
        case EmitterKind::directional: {
            const LightSample light = sample_light<float>(m_scene.lights[e.index], p);
            s.to_light = light.to_light;
            s.distance = light.distance;
            s.radiance = light.irradiance;
            s.pdf = e.choice;
            s.delta = true;
            break;
        }
    }
    return s;
}

float EmitterTable::triangle_pdf(uint32_t triangle, Vec3 dir, float t) const {
    if (m_triangle_entry.empty() || m_triangle_entry[triangle] < 0) return 0.0f;
    return surface_pdf(m_entries[static_cast<size_t>(m_triangle_entry[triangle])], dir, t);
}

float EmitterTable::area_pdf(size_t light, Vec3 dir, float t) const {
    if (m_light_entry[light] < 0) return 0.0f;
    return surface_pdf(m_entries[static_cast<size_t>(m_light_entry[light])], dir, t);
}

float EmitterTable::environment_pdf(Vec3 dir, Vec3 n) const {
    if (m_environment_entry < 0) return 0.0f;
    const Entry& e = m_entries[static_cast<size_t>(m_environment_entry)];
    const auto& env = std::get<EnvironmentLight>(m_scene.lights[e.index]);
    const float pdf = env.map ? env.map->pdf(dir) : cosine_hemisphere_pdf(dot(n, dir));
    return e.choice * pdf;
}

}  // namespace hikari
