#include "hikari/integrators/path/emitters.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "hikari/core/aabb.h"
#include "hikari/core/color.h"
#include "hikari/shading/lights.h"

namespace hikari {

namespace {

constexpr float k_pi = std::numbers::pi_v<float>;

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
    // Powers: what each emits in all, Φ = π·L·A for a one-sided face; the lights' own estimates
    // (light_power) for the scene's lights.
    const TriangleSet& tris = scene.triangles;
    for (uint32_t i = 0; i < tris.size(); ++i) {
        const Vec3 emission = scene.materials[tris.material[i]].emission;
        if (max_component(emission) <= 0.0f) continue;
        if (m_triangle_entry.empty()) m_triangle_entry.assign(tris.size(), -1);
        const auto& [a, b, c] = tris.indices[i];
        Entry e;
        e.triangle = true;
        e.index = i;
        e.corner = tris.positions[a];
        e.edge1 = tris.positions[b] - e.corner;
        e.edge2 = tris.positions[c] - e.corner;
        const Vec3 n = cross(e.edge1, e.edge2);
        const float len = length(n);
        e.front = len > 0.0f ? n / len : Vec3(0.0f);
        e.area = 0.5f * len;
        e.radiance = emission;
        m_triangle_entry[i] = add(e, k_pi * luminance(emission) * e.area);
    }
    m_light_entry.assign(scene.lights.size(), -1);
    for (uint32_t l = 0; l < scene.lights.size(); ++l) {
        Entry e;
        e.index = l;
        m_light_entry[l] = add(e, light_power(scene.lights[l], radius));
        if (light_as<EnvironmentLight>(scene.lights[l])) m_environment_light = static_cast<int>(l);
    }
    for (size_t i = 0; i < m_entries.size(); ++i)
        m_entries[i].choice = static_cast<float>(powers[i] / total);
}

EmitterSample EmitterTable::sample_triangle(const Entry& e, Vec3 p, Vec2 u) {
    // Uniform over the area, the square folded by the square root (Turk 1990).
    EmitterSample s;
    const float su = std::sqrt(u.x);
    const Vec3 y = e.corner + (su * (1.0f - u.y)) * e.edge1 + (su * u.y) * e.edge2;
    const Vec3 d = y - p;
    const float r2 = dot(d, d);
    if (!(r2 > 0.0f)) return s;
    s.distance = std::sqrt(r2);
    s.to_light = d / s.distance;
    s.pdf = emitting_surface_pdf(e.front, e.area, false, s.to_light, s.distance, e.choice);
    if (s.pdf > 0.0f) s.radiance = e.radiance;
    return s;
}

EmitterSample EmitterTable::sample(Vec3 p, Vec3 n, float u_choice, Vec2 u) const {
    if (m_cdf.empty()) return {};
    const double target = static_cast<double>(u_choice) * m_cdf.back();
    const size_t chosen = std::min<size_t>(
        static_cast<size_t>(std::upper_bound(m_cdf.begin(), m_cdf.end(), target) - m_cdf.begin()),
        m_cdf.size() - 1);
    const Entry& e = m_entries[chosen];
    if (e.triangle) return sample_triangle(e, p, u);
    return sample_incident(m_scene.lights[e.index], p, n, u, e.choice);
}

float EmitterTable::triangle_pdf(uint32_t triangle, Vec3 dir, float t) const {
    if (m_triangle_entry.empty() || m_triangle_entry[triangle] < 0) return 0.0f;
    const Entry& e = m_entries[static_cast<size_t>(m_triangle_entry[triangle])];
    return emitting_surface_pdf(e.front, e.area, false, dir, t, e.choice);
}

float EmitterTable::light_pdf(size_t light, Vec3 n, Vec3 dir, float t) const {
    if (m_light_entry[light] < 0) return 0.0f;
    const float choice = m_entries[static_cast<size_t>(m_light_entry[light])].choice;
    return incident_pdf(m_scene.lights[light], n, dir, t, choice);
}

float EmitterTable::environment_pdf(Vec3 dir, Vec3 n) const {
    if (m_environment_light < 0) return 0.0f;
    return light_pdf(static_cast<size_t>(m_environment_light), n, dir, 0.0f);
}

}  // namespace hikari
