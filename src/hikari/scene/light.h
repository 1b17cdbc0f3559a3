#pragma once
// Light sources of the lecture ("CG でよく使われる光源") as plain data: a closed set of kinds.
// What each delivers to a surface point is in shading/lights/ (one file per kind).

#include <memory>
#include <optional>
#include <variant>

#include "hikari/core/vec.h"
#include "hikari/scene/environment_map.h"

namespace hikari {

/// Light from one point; irradiance falls off as intensity / d² (or not at all, as POV-Ray's
/// default light without fade). Sampled by shading/lights/point_light.h.
struct PointLight {
    Vec3 position;
    Vec3 intensity;
    bool inverse_square = true;  ///< false: irradiance = intensity at any distance
};

/// Light from infinitely far away (the sun); no falloff. Sampled by
/// shading/lights/directional_light.h.
struct DirectionalLight {
    Vec3 direction;  ///< unit direction in which the light travels (L_in), world space
    Vec3 intensity;
};

/// A parallelogram that emits radiance L (the lecture's area light, "a set of point lights"):
/// its points are corner + a·edge1 + b·edge2 for a, b in [0, 1], and it shines from the side
/// edge1 × edge2 points to (from both when two_sided). Each patch dA acts as a point light of
/// intensity L·cos θ′·dA (θ′ between the light's normal and the direction to the lit point).
/// Sampled by shading/lights/area_light.h; its shadows are soft.
struct AreaLight {
    Vec3 corner;
    Vec3 edge1;
    Vec3 edge2;
    Vec3 radiance;  ///< L, the same at every point and in every direction it emits
    bool two_sided = false;

    Vec3 centre() const { return corner + 0.5f * (edge1 + edge2); }
    /// edge1 × edge2: the emitting side's normal, its length the light's area.
    Vec3 area_normal() const { return cross(edge1, edge2); }
};

/// Light from every direction (the lecture's environment light, "a set of directional
/// lights"): a constant radiance, or a latitude–longitude map (scene/environment_map.h) scaled
/// by `radiance`. Escaping rays see it. Sampled by shading/lights/environment_light.h.
struct EnvironmentLight {
    Vec3 radiance{1.0f};  ///< the constant radiance, or the map's scale
    /// The map, shared by copies of the scene; null for a constant radiance.
    std::shared_ptr<const EnvironmentMap> map;

    /// The radiance arriving from unit direction `toward` (the direction to the sky).
    Vec3 radiance_from(Vec3 toward) const {
        return map ? radiance * map->radiance_from(toward) : radiance;
    }
};

/// Every light kind. Adding one: its struct here and in this list, its sampling routine in
/// shading/lights/ (included by shading/lights.h), its key in io/scene_json.cpp and
/// docs/scene-format.md.
using Light = std::variant<PointLight, DirectionalLight, AreaLight, EnvironmentLight>;

/// Whether `light` is one point or one direction (point, directional), which a single shadow
/// ray or shadow-map lookup answers; area and environment lights are integrated over many.
/// The point a shadow map or shadow volume sees `light` from: a point light's position, an area
/// light's centre; none for directional and environment lights.
inline std::optional<Vec3> light_position(const Light& light) {
    if (const auto* p = std::get_if<PointLight>(&light)) return p->position;
    if (const auto* a = std::get_if<AreaLight>(&light)) return a->centre();
    return std::nullopt;
}

inline bool is_delta_light(const Light& light) {
    return std::holds_alternative<PointLight>(light) ||
           std::holds_alternative<DirectionalLight>(light);
}

}  // namespace hikari
