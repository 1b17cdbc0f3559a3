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

EmitterTable::EmitterTable(const Scene& scene) {
    const float radius = scene_radius(scene);
    double total = 0.0;
    std::vector<double> powers;
    const auto add = [&](const EmitterEntry& entry, double power) -> int32_t {
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
        EmitterEntry e;
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
        EmitterEntry e;
        e.index = l;
        m_light_entry[l] = add(e, light_power(scene.lights[l], radius));
        if (light_as<EnvironmentLight>(scene.lights[l]))
            m_view.environment_light = static_cast<int>(l);
    }
    for (size_t i = 0; i < m_entries.size(); ++i)
        m_entries[i].choice = static_cast<float>(powers[i] / total);
    m_view.entries = FlatView<EmitterEntry>(std::span<const EmitterEntry>(m_entries));
    m_view.cdf = FlatView<double>(std::span<const double>(m_cdf));
    m_view.triangle_entry = FlatView<int32_t>(std::span<const int32_t>(m_triangle_entry));
    m_view.light_entry = FlatView<int32_t>(std::span<const int32_t>(m_light_entry));
    m_view.lights = scene.lights.data();
}

}  // namespace hikari
