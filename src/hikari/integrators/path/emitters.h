#pragma once
// Everything that emits light, as the path tracer aims at it (next-event estimation): the
// scene's lights and every triangle whose material has an emission. One emitter is chosen per
// path vertex with probability proportional to its power (an estimate of the light it sends
// into the scene), then one point or direction on it. The densities are kept per solid angle so
// that a direction found by BSDF sampling can be weighed against light sampling (Veach 1997,
// multiple importance sampling). The lights' own sampling, densities and powers are theirs
// (shading/lights.h); this table only chooses among them.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "hikari/core/flat_view.h"
#include "hikari/core/host_device.h"
#include "hikari/core/vec.h"
#include "hikari/scene/scene.h"
#include "hikari/shading/light_sample.h"
#include "hikari/shading/lights.h"

namespace hikari {

/// One light sample seen from a surface point (the lights' own, shading/light_sample.h).
using EmitterSample = IncidentSample;

/// One emitter: an emissive triangle or a light of the scene.
struct EmitterEntry {
    bool triangle = false;
    uint32_t index = 0;  ///< a triangle, or a light of Scene::lights
    float choice = 0;    ///< the probability of choosing it
    // Triangles: corner + a·edge1 + b·edge2 (a + b ≤ 1), unit normal, area, emission.
    Vec3 corner, edge1, edge2;
    Vec3 front{0.0f};
    float area = 0;
    Vec3 radiance{0.0f};
};

/// An EmitterTable's arrays as flat views, with its sampling and densities: what the CPU path
/// tracer calls (views of the table's own arrays) and the GPU's kernels too (views of copies).
struct EmitterView {
    FlatView<EmitterEntry> entries;
    FlatView<double> cdf;              ///< running sum of the entries' powers
    FlatView<int32_t> triangle_entry;  ///< entry of each triangle, -1: none (empty: none emits)
    FlatView<int32_t> light_entry;     ///< entry of each scene light, -1: none
    const Light* lights = nullptr;     ///< Scene::lights
    int32_t environment_light = -1;    ///< the environment's index in Scene::lights

    /// Whether nothing in the scene emits light.
    HIKARI_HD bool empty() const { return cdf.empty(); }

    /// One light for a point at `p` with unit normal `n`: the emitter chosen by `u_choice`, the
    /// point or direction on it by `u`. radiance 0 where the sample carries none (the back of a
    /// one-sided light, a zero-power emitter).
    HIKARI_HD EmitterSample sample(Vec3 p, Vec3 n, float u_choice, Vec2 u) const {
        if (cdf.empty()) return {};
        // The first entry whose running sum passes the target (std::upper_bound).
        const double target = static_cast<double>(u_choice) * cdf[cdf.size() - 1];
        size_t low = 0, high = cdf.size();
        while (low < high) {
            const size_t mid = low + (high - low) / 2;
            if (target < cdf[mid])
                high = mid;
            else
                low = mid + 1;
        }
        const EmitterEntry& e = entries[low < cdf.size() ? low : cdf.size() - 1];
        if (e.triangle) return sample_triangle(e, p, u);
        return sample_incident(lights[e.index], p, n, u, e.choice);
    }

    /// The density (per steradian, choice included) with which sample() at a point `p` with
    /// normal `n` draws the direction `dir` toward emissive triangle `triangle`, met at distance
    /// `t`.
    HIKARI_HD float triangle_pdf(uint32_t triangle, Vec3 dir, float t) const {
        if (triangle_entry.empty() || triangle_entry[triangle] < 0) return 0.0f;
        const EmitterEntry& e = entries[static_cast<size_t>(triangle_entry[triangle])];
        return emitting_surface_pdf(e.front, e.area, false, dir, t, e.choice);
    }
    /// The same for light `light` (an index into Scene::lights) met at distance `t` from a point
    /// with normal `n`; 0 for delta lights.
    HIKARI_HD float light_pdf(size_t light, Vec3 n, Vec3 dir, float t) const {
        if (light_entry[light] < 0) return 0.0f;
        const float choice = entries[static_cast<size_t>(light_entry[light])].choice;
        return incident_pdf(lights[light], n, dir, t, choice);
    }
    /// The same for the environment seen along `dir` from a point with normal `n`.
    HIKARI_HD float environment_pdf(Vec3 dir, Vec3 n) const {
        if (environment_light < 0) return 0.0f;
        return light_pdf(static_cast<size_t>(environment_light), n, dir, 0.0f);
    }

    /// Whether triangle `triangle` emits (its material has an emission).
    HIKARI_HD bool emits(uint32_t triangle) const {
        return !triangle_entry.empty() && triangle_entry[triangle] >= 0;
    }

    /// The triangle `e`'s sample toward `p` for the pair `u`: uniform over the area, the square
    /// folded by the square root (Turk 1990).
    HIKARI_HD static EmitterSample sample_triangle(const EmitterEntry& e, Vec3 p, Vec2 u) {
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
};

/// The emitters of a scene, built once per render; view() is what samples them.
class EmitterTable {
  public:
    /// The emitters of `scene` (which must outlive the table).
    explicit EmitterTable(const Scene& scene);
    EmitterTable(const EmitterTable&) = delete;
    EmitterTable& operator=(const EmitterTable&) = delete;

    /// The table as flat views of its own arrays.
    const EmitterView& view() const { return m_view; }

    /// EmitterView's, for the CPU's path tracer.
    bool empty() const { return m_view.empty(); }
    EmitterSample sample(Vec3 p, Vec3 n, float u_choice, Vec2 u) const {
        return m_view.sample(p, n, u_choice, u);
    }
    float triangle_pdf(uint32_t triangle, Vec3 dir, float t) const {
        return m_view.triangle_pdf(triangle, dir, t);
    }
    float light_pdf(size_t light, Vec3 n, Vec3 dir, float t) const {
        return m_view.light_pdf(light, n, dir, t);
    }
    float environment_pdf(Vec3 dir, Vec3 n) const { return m_view.environment_pdf(dir, n); }
    bool emits(uint32_t triangle) const { return m_view.emits(triangle); }

    /// The arrays behind view(), for a copy on a device.
    std::span<const EmitterEntry> entries() const { return m_entries; }
    std::span<const double> cdf() const { return m_cdf; }
    std::span<const int32_t> triangle_entries() const { return m_triangle_entry; }
    std::span<const int32_t> light_entries() const { return m_light_entry; }

  private:
    std::vector<EmitterEntry> m_entries;
    std::vector<double> m_cdf;              ///< running sum of the entries' powers
    std::vector<int32_t> m_triangle_entry;  ///< entry of each triangle, -1: none
    std::vector<int32_t> m_light_entry;     ///< entry of each scene light, -1: none
    EmitterView m_view;
};

}  // namespace hikari
