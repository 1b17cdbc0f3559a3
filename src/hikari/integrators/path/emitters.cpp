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

/// Twice the area of triangle i, and its front normal (unit, counter-clockwise side).
float triangle_double_area(const TriangleSet& tris, uint32_t i, Vec3& normal) {
    const auto& [a, b, c] = tris.indices[i];
    const Vec3 n =
        cross(tris.positions[b] - tris.positions[a], tris.positions[c] - tris.positions[a]);
    const float len = length(n);
    normal = len > 0.0f ? n / len : Vec3(0.0f);
    return len;
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
    const auto add = [&](EmitterKind kind, uint32_t index, double power) -> int32_t {
        if (!(power > 0.0) || !std::isfinite(power)) return -1;
        m_entries.push_back({kind, index});
        total += power;
        m_cdf.push_back(total);
        return static_cast<int32_t>(m_entries.size() - 1);
    };
    // Powers: what each emits in all, Φ = π·L·A for a one-sided face, 4π·I for a point light;
    // lights at infinity by what crosses the scene's disc.
    const TriangleSet& tris = scene.triangles;
    for (uint32_t i = 0; i < tris.size(); ++i) {
        const Vec3 emission = scene.materials[tris.material[i]].emission;
        if (max_component(emission) <= 0.0f) continue;
        if (m_triangle_entry.empty()) m_triangle_entry.assign(tris.size(), -1);
        Vec3 normal;
        const float area = 0.5f * triangle_double_area(tris, i, normal);
        m_triangle_entry[i] = add(EmitterKind::triangle, i, k_pi * luminance(emission) * area);
    }
    m_light_entry.assign(scene.lights.size(), -1);
    for (uint32_t l = 0; l < scene.lights.size(); ++l) {
        const Light& light = scene.lights[l];
        if (const auto* area = std::get_if<AreaLight>(&light)) {
            const double sides = area->two_sided ? 2.0 : 1.0;
            m_light_entry[l] =
                add(EmitterKind::area, l,
                    sides * k_pi * luminance(area->radiance) * length(area->area_normal()));
        } else if (const auto* env = std::get_if<EnvironmentLight>(&light)) {
            m_light_entry[l] = m_environment_entry = add(
                EmitterKind::environment, l, k_pi * k_pi * radius * radius * mean_luminance(*env));
        } else if (const auto* point = std::get_if<PointLight>(&light)) {
            m_light_entry[l] = add(EmitterKind::point, l, 4.0 * k_pi * luminance(point->intensity));
        } else if (const auto* sun = std::get_if<DirectionalLight>(&light)) {
            m_light_entry[l] = add(EmitterKind::directional, l,
                                   k_pi * radius * radius * luminance(sun->intensity));
        }
    }
}

float EmitterTable::choice_probability(size_t entry) const {
    const double below = entry == 0 ? 0.0 : m_cdf[entry - 1];
    return static_cast<float>((m_cdf[entry] - below) / m_cdf.back());
}

EmitterSample EmitterTable::sample(Vec3 p, Vec3 n, float u_choice, Vec2 u) const {
    EmitterSample s;
    if (m_cdf.empty()) return s;
    const double target = static_cast<double>(u_choice) * m_cdf.back();
    const size_t entry = std::min<size_t>(
        static_cast<size_t>(std::upper_bound(m_cdf.begin(), m_cdf.end(), target) - m_cdf.begin()),
        m_cdf.size() - 1);
    const float choice = choice_probability(entry);
    const Entry& e = m_entries[entry];
    // A point y on a surface emitter with front normal n_y: per solid angle the density of a
    // uniform area sample is r² / (A cos θ_y).
    const auto surface_point = [&](Vec3 y, Vec3 front, float area, Vec3 radiance, bool two_sided) {
        const Vec3 d = y - p;
        const float r2 = dot(d, d);
        s.distance = std::sqrt(r2);
        s.to_light = d / s.distance;
        float cos_y = -dot(front, s.to_light);
        if (two_sided) cos_y = std::abs(cos_y);
        if (!(cos_y > 0.0f) || !(r2 > 0.0f)) return;
        s.radiance = radiance;
        s.pdf = choice * r2 / (area * cos_y);
    };
    switch (e.kind) {
        case EmitterKind::triangle: {
            const TriangleSet& tris = m_scene.triangles;
            const auto& [a, b, c] = tris.indices[e.index];
            Vec3 front;
            const float area = 0.5f * triangle_double_area(tris, e.index, front);
            // Uniform over the triangle: the square folded by the square root (Turk 1990).
            const float su = std::sqrt(u.x);
            const Vec3 y = (1.0f - su) * tris.positions[a] + su * (1.0f - u.y) * tris.positions[b] +
                           su * u.y * tris.positions[c];
            surface_point(y, front, area, m_scene.materials[tris.material[e.index]].emission,
                          false);
            break;
        }
        case EmitterKind::area: {
            const AreaLight& light = std::get<AreaLight>(m_scene.lights[e.index]);
            const Vec3 normal = light.area_normal();
            const float area = length(normal);
            surface_point(light.corner + u.x * light.edge1 + u.y * light.edge2, normal / area, area,
                          light.radiance, light.two_sided);
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
                s.pdf = choice * d.pdf;
            } else {
                s.to_light = cosine_hemisphere_direction(n, u);
                const float pdf = cosine_hemisphere_pdf(dot(n, s.to_light));
                if (!(pdf > 0.0f)) break;
                s.radiance = env.radiance;
                s.pdf = choice * pdf;
            }
            break;
        }
        case EmitterKind::point:
        case EmitterKind::directional: {
            const LightSample light = sample_light<float>(m_scene.lights[e.index], p);
            s.to_light = light.to_light;
            s.distance = light.distance;
            s.radiance = light.irradiance;
            s.pdf = choice;
            s.delta = true;
            break;
        }
    }
    return s;
}

float EmitterTable::triangle_pdf(uint32_t triangle, Vec3 dir, float t) const {
    if (m_triangle_entry.empty() || m_triangle_entry[triangle] < 0) return 0.0f;
    Vec3 front;
    const float area = 0.5f * triangle_double_area(m_scene.triangles, triangle, front);
    const float cos_y = -dot(front, dir);
    if (!(cos_y > 0.0f) || !(area > 0.0f)) return 0.0f;
    return choice_probability(static_cast<size_t>(m_triangle_entry[triangle])) * t * t /
           (area * cos_y);
}

float EmitterTable::area_pdf(size_t light, Vec3 dir, float t) const {
    if (m_light_entry[light] < 0) return 0.0f;
    const AreaLight& a = std::get<AreaLight>(m_scene.lights[light]);
    const Vec3 normal = a.area_normal();
    const float area = length(normal);
    float cos_y = -dot(normal, dir) / area;
    if (a.two_sided) cos_y = std::abs(cos_y);
    if (!(cos_y > 0.0f)) return 0.0f;
    return choice_probability(static_cast<size_t>(m_light_entry[light])) * t * t / (area * cos_y);
}

float EmitterTable::environment_pdf(Vec3 dir, Vec3 n) const {
    if (m_environment_entry < 0) return 0.0f;
    const auto& env = std::get<EnvironmentLight>(
        m_scene.lights[m_entries[static_cast<size_t>(m_environment_entry)].index]);
    const float pdf = env.map ? env.map->pdf(dir) : cosine_hemisphere_pdf(dot(n, dir));
    return choice_probability(static_cast<size_t>(m_environment_entry)) * pdf;
}

}  // namespace hikari
