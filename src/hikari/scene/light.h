#pragma once
// Light sources of the lecture ("CG でよく使われる光源") as plain data: a closed set of kinds.
// What each delivers to a surface point is in shading/lights/ (one file per kind).

#include <functional>
#include <memory>
#include <utility>
#include <variant>

#include "hikari/core/vec.h"
#include "hikari/core/visit.h"
#include "hikari/scene/environment_map.h"

namespace hikari {

/// How a light moves with its scene (a model's transform, the rebase to the camera): where a
/// point goes, where an edge vector goes, and where a unit direction goes (unit again).
struct LightMove {
    std::function<Vec3(Vec3)> point;
    std::function<Vec3(Vec3)> vector;
    std::function<Vec3(Vec3)> direction;
};

/// Light from one point; irradiance falls off as intensity / d² (or not at all, as POV-Ray's
/// default light without fade). Sampled by shading/lights/point_light.h.
struct PointLight {
    Vec3 position;
    Vec3 intensity;
    bool inverse_square = true;  ///< false: irradiance = intensity at any distance

    void move(const LightMove& m) { position = m.point(position); }
};

/// Light from infinitely far away (the sun); no falloff. Sampled by
/// shading/lights/directional_light.h.
struct DirectionalLight {
    Vec3 direction;  ///< unit direction in which the light travels (L_in), world space
    Vec3 intensity;

    void move(const LightMove& m) { direction = m.direction(direction); }
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

    HIKARI_HD Vec3 centre() const { return corner + 0.5f * (edge1 + edge2); }
    /// edge1 × edge2: the emitting side's normal, its length the light's area.
    HIKARI_HD Vec3 area_normal() const { return cross(edge1, edge2); }

    void move(const LightMove& m) {
        corner = m.point(corner);
        edge1 = m.vector(edge1);
        edge2 = m.vector(edge2);
    }
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

    /// At infinity, its map fixed to the world: it stays.
    void move(const LightMove&) {}
};

/// The lecture's point light restricted to a cone (a spot light): intensity I / d² inside the cone
/// about `direction`, with a smooth edge. At angle θ from the axis it delivers
///   I · s(cos θ) / d²,  s(c) = smoothstep(cos outer, cos inner, c) = t²(3 − 2t),
///   t = clamp((c − cos outer) / (cos inner − cos outer), 0, 1),
/// so full intensity within `inner_angle`, none beyond `outer_angle` (a hard edge when they are
/// equal). Sampled by shading/lights/spot_light.h.
struct SpotLight {
    Vec3 position;
    Vec3 direction;  ///< unit axis of the cone, the way the light shines, world space
    Vec3 intensity;
    float inner_angle = 30;  ///< half-angle from the axis of full intensity, degrees, (0, 90]
    float outer_angle = 45;  ///< half-angle beyond which nothing is lit, degrees, ≥ inner_angle

    void move(const LightMove& m) {
        position = m.point(position);
        direction = m.direction(direction);
    }
};

/// Every light kind. Adding one: its struct here and in this list, one file in shading/lights/
/// with its per-kind operations (included by shading/lights.h), its parser in
/// io/scene/scene_json.cpp and its keys in docs/scene-format.md (docs/architecture.md). Each
/// per-kind operation is an exhaustive visit (visit_light), so a kind left out fails to compile.
using Light = std::variant<PointLight, SpotLight, DirectionalLight, AreaLight, EnvironmentLight>;

/// `f(kind)` for the kind `light` holds. `f` must take every kind (an Overloaded set of one
/// lambda per kind, or a generic lambda calling a per-kind function): a kind it cannot take is a
/// compile error here.
template <class Function>
HIKARI_HD decltype(auto) visit_light(const Light& light, Function&& f) {
    return visit_kind(light, std::forward<Function>(f));
}
/// Moves `light` with its scene (every kind's `move`).
inline void move_light(Light& light, const LightMove& m) {
    std::visit([&](auto& kind) { kind.move(m); }, light);
}

}  // namespace hikari
