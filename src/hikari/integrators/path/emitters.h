#pragma once
// Everything that emits light, as the path tracer aims at it (next-event estimation): the
// scene's lights and every triangle whose material has an emission. One emitter is chosen per
// path vertex with probability proportional to its power (an estimate of the light it sends
// into the scene), then one point or direction on it. The densities are kept per solid angle so
// that a direction found by BSDF sampling can be weighed against light sampling (Veach 1997,
// multiple importance sampling). The lights' own sampling, densities and powers are theirs
// (shading/lights.h); this table only chooses among them.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "hikari/core/vec.h"
#include "hikari/scene/scene.h"
#include "hikari/shading/light_sample.h"

namespace hikari {

/// One light sample seen from a surface point (the lights' own, shading/light_sample.h).
using EmitterSample = IncidentSample;

class EmitterTable {
  public:
    /// The emitters of `scene` (which must outlive the table).
    explicit EmitterTable(const Scene& scene);

    /// Whether nothing in the scene emits light.
    bool empty() const { return m_cdf.empty(); }

    /// One light for a point at `p` with unit normal `n`: the emitter chosen by `u_choice`, the
    /// point or direction on it by `u`. radiance 0 where the sample carries none (the back of a
    /// one-sided light, a zero-power emitter).
    EmitterSample sample(Vec3 p, Vec3 n, float u_choice, Vec2 u) const;

    /// The density (per steradian, choice included) with which sample() at a point `p` with
    /// normal `n` draws the direction `dir` toward emissive triangle `triangle`, met at distance
    /// `t`.
    float triangle_pdf(uint32_t triangle, Vec3 dir, float t) const;
    /// The same for light `light` (an index into Scene::lights) met at distance `t` from a point
    /// with normal `n`; 0 for delta lights.
    float light_pdf(size_t light, Vec3 n, Vec3 dir, float t) const;
    /// The same for the environment seen along `dir` from a point with normal `n`.
    float environment_pdf(Vec3 dir, Vec3 n) const;

    /// Whether triangle `triangle` emits (its material has an emission).
    bool emits(uint32_t triangle) const {
        return !m_triangle_entry.empty() && m_triangle_entry[triangle] >= 0;
    }

  private:
    /// One emitter: an emissive triangle or a light of the scene.
    struct Entry {
        bool triangle = false;
        uint32_t index;    ///< a triangle, or a light of Scene::lights
        float choice = 0;  ///< the probability of choosing it
        // Triangles: corner + a·edge1 + b·edge2 (a + b ≤ 1), unit normal, area, emission.
        Vec3 corner, edge1, edge2;
        Vec3 front{0.0f};
        float area = 0;
        Vec3 radiance{0.0f};
    };

    /// The triangle `entry`'s sample toward `p` for the pair `u`.
    static EmitterSample sample_triangle(const Entry& entry, Vec3 p, Vec2 u);

    const Scene& m_scene;
    std::vector<Entry> m_entries;
    std::vector<double> m_cdf;              ///< running sum of the entries' powers
    std::vector<int32_t> m_triangle_entry;  ///< entry of each triangle, -1: none
    std::vector<int32_t> m_light_entry;     ///< entry of each scene light, -1: none
    int32_t m_environment_light = -1;       ///< the environment's index in Scene::lights
};

}  // namespace hikari
