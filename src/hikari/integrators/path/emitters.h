#pragma once
// Everything that emits light, as the path tracer aims at it (next-event estimation): the
// scene's lights and every triangle whose material has an emission. One emitter is chosen per
// path vertex with probability proportional to its power (an estimate of the light it sends
// into the scene), then one point or direction on it. The densities are kept per solid angle so
// that a direction found by BSDF sampling can be weighed against light sampling (Veach 1997,
// multiple importance sampling).

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "hikari/core/vec.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// What one emitter is.
enum class EmitterKind : uint8_t { triangle, area, environment, point, directional };

/// One light sample seen from a surface point.
struct EmitterSample {
    Vec3 to_light;        ///< unit direction from the point toward the light
    float distance = 0;   ///< to the sampled point; infinity for directions
    Vec3 radiance{0.0f};  ///< L arriving from there (for a delta light: its irradiance)
    float pdf = 0;        ///< per steradian, the choice of the emitter included; for a
                          ///< delta light the probability of choosing it
    bool delta = false;   ///< a point or directional light: no BSDF sample can find it
};

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
    /// The same for area light `light` (an index into Scene::lights).
    float area_pdf(size_t light, Vec3 dir, float t) const;
    /// The same for the environment seen along `dir` from a point with normal `n`.
    float environment_pdf(Vec3 dir, Vec3 n) const;

    /// Whether triangle `triangle` emits (its material has an emission).
    bool emits(uint32_t triangle) const {
        return !m_triangle_entry.empty() && m_triangle_entry[triangle] >= 0;
    }

  private:
    /// One emitter, with what sampling it reads, in one place.
    struct Entry {
        EmitterKind kind;
        uint32_t index;    ///< a triangle, or a light of Scene::lights
        float choice = 0;  ///< the probability of choosing it
        // Surfaces (triangles, area lights): corner + a·edge1 + b·edge2.
        Vec3 corner, edge1, edge2;
        Vec3 front{0.0f};  ///< unit normal of the emitting side
        float area = 0;
        Vec3 radiance{0.0f};  ///< emitted radiance
        bool two_sided = false;
    };

    /// The density per solid angle of `entry`'s uniform area samples seen along unit `dir` at
    /// distance `t`: choice · t² / (A cos θ_y); 0 from behind a one-sided face.
    static float surface_pdf(const Entry& entry, Vec3 dir, float t);

    const Scene& m_scene;
    std::vector<Entry> m_entries;
    std::vector<double> m_cdf;              ///< running sum of the entries' powers
    std::vector<int32_t> m_triangle_entry;  ///< entry of each triangle, -1: none
    std::vector<int32_t> m_light_entry;     ///< entry of each scene light, -1: none
    int32_t m_environment_entry = -1;
};

}  // namespace hikari
