#pragma once
// The area light's sampling routines. Every patch dA of the parallelogram is a point light of
// intensity L·cos θ′·dA, so a point p receives from it
//   E = ∫ L·cos θ′ / r² dA      (r = |y − p|, θ′ between the light's normal and p − y)
// times the lecture's reflection term. Sampled uniformly over the area (pdf 1/A), one sample
// y is a point light of irradiance L·A·cos θ′ / r² at p; the light seen from far away is that
// point light at its centre.

#include <cmath>
#include <numbers>
#include <optional>
#include <string_view>
#include <utility>

#include "hikari/core/color.h"
#include "hikari/core/lanes.h"
#include "hikari/core/vec.h"
#include "hikari/scene/light.h"
#include "hikari/shading/light_sample.h"
#include "hikari/shading/light_shadow_view.h"

namespace hikari {

/// The light of `light` toward `p` from the light's point corner + u.x·edge1 + u.y·edge2,
/// weighted by 1 / pdf = A: irradiance L·A·cos θ′ / r², zero where p is behind a one-sided
/// light.
template <class F>
HIKARI_INLINE HIKARI_HD LightSampleT<F> sample_area_light(const AreaLight& light, const Vec3T<F>& p,
                                                          const F& u, const F& v) {
    const Vec3T<F> y =
        Vec3T<F>(light.corner) + Vec3T<F>(light.edge1) * u + Vec3T<F>(light.edge2) * v;
    const Vec3T<F> d = y - p;
    const F d2 = dot(d, d);
    const F distance = sqrt_of(d2);
    const Vec3T<F> to_light = d / distance;
    // A·cos θ′ = (edge1 × edge2)·(p − y) / r.
    F area_cos = -dot(Vec3T<F>(light.area_normal()), to_light);
    if (light.two_sided) area_cos = select(area_cos < F(0.0f), -area_cos, area_cos);
    area_cos = select(area_cos > F(0.0f), area_cos, F(0.0f));
    return {to_light, distance, Vec3T<F>(light.radiance) * (area_cos / d2)};
}

/// Where the ray from `origin` along unit `direction` meets the emitting side of `light` (either
/// side when two-sided) strictly between 0 and `t_max`: the distance, or t_max when it does not.
/// What camera rays see of the light: its radiance L.
HIKARI_HD inline float area_light_hit(const AreaLight& light, Vec3 origin, Vec3 direction,
                                      float t_max) {
    const Vec3 n = light.area_normal();
    const float facing = dot(n, direction);
    if (facing == 0.0f || (!light.two_sided && facing > 0.0f)) return t_max;
    const float t = dot(n, light.corner - origin) / facing;
    if (!(t > 0.0f && t < t_max)) return t_max;
    const Vec3 x = origin + t * direction - light.corner;
    const float area2 = dot(n, n);
    const float a = dot(x, cross(light.edge2, n)) / area2,
                b = dot(x, cross(n, light.edge1)) / area2;
    return a >= 0.0f && a <= 1.0f && b >= 0.0f && b <= 1.0f ? t : t_max;
}

/// The area light as one point light at its centre (what a light far away and small is; also
/// what shadow maps and shadow volumes, which see from one point, take it for).
template <class F>
HIKARI_INLINE HIKARI_HD LightSampleT<F> sample_light(const AreaLight& light, const Vec3T<F>& p) {
    return sample_area_light<F>(light, p, F(0.5f), F(0.5f));
}

/// One stratified sample among many: uniform over the area (weight A).
inline LightSample sample_light_at(const AreaLight& light, Vec3 p, Vec3, Vec2 uv) {
    return sample_area_light<float>(light, p, uv.x, uv.y);
}

/// The density per solid angle, times `choice`, of uniform samples over an emitting surface of
/// area `area` and unit normal `front` (its emitting side; both when two-sided) seen along unit
/// `dir` at distance `t`: choice · t² / (A cos θ_y); 0 from behind a one-sided face. Area
/// lights and emissive triangles share it.
HIKARI_HD inline float emitting_surface_pdf(Vec3 front, float area, bool two_sided, Vec3 dir,
                                            float t, float choice) {
    float cos_y = -dot(front, dir);
    if (two_sided) cos_y = std::abs(cos_y);
    if (!(cos_y > 0.0f) || !(area > 0.0f)) return 0.0f;
    return choice * t * t / (area * cos_y);
}

/// The light's unit emitting normal (zero for a degenerate light) and its area.
HIKARI_HD inline std::pair<Vec3, float> area_light_frame(const AreaLight& light) {
    const Vec3 n = light.area_normal();
    const float len = length(n);
    return {len > 0.0f ? n / len : Vec3(0.0f), len};
}

/// The path tracer's sample: a point uniform over the area for the pair `u`, its density per
/// solid angle; radiance 0 where the point sees the back of a one-sided light.
HIKARI_HD inline IncidentSample sample_incident(const AreaLight& light, Vec3 p, Vec3, Vec2 u,
                                                float choice) {
    IncidentSample s;
    const Vec3 y = light.corner + u.x * light.edge1 + u.y * light.edge2;
    const Vec3 d = y - p;
    const float r2 = dot(d, d);
    if (!(r2 > 0.0f)) return s;
    s.distance = std::sqrt(r2);
    s.to_light = d / s.distance;
    const auto [front, area] = area_light_frame(light);
    s.pdf = emitting_surface_pdf(front, area, light.two_sided, s.to_light, s.distance, choice);
    if (s.pdf > 0.0f) s.radiance = light.radiance;
    return s;
}

/// The density with which sample_incident draws `dir`, met on the light at distance `t`.
HIKARI_HD inline float incident_pdf(const AreaLight& light, Vec3, Vec3 dir, float t, float choice) {
    const auto [front, area] = area_light_frame(light);
    return emitting_surface_pdf(front, area, light.two_sided, dir, t, choice);
}

/// Φ = π·L·A from each emitting side.
inline double light_power(const AreaLight& light, float) {
    return (light.two_sided ? 2.0 : 1.0) * std::numbers::pi_v<float> * luminance(light.radiance) *
           area_light_frame(light).second;
}

inline std::optional<Vec3> light_position(const AreaLight& light) { return light.centre(); }

/// Seen from its centre (a cube map there), with half its mean edge as the radius of PCSS.
inline LightShadowView shadow_view(const AreaLight& light) {
    return {ShadowProjection::cube, light.centre(), Vec3(0.0f), 0.0f,
            0.25f * (length(light.edge1) + length(light.edge2))};
}

constexpr bool is_delta(const AreaLight&) { return false; }
constexpr std::string_view light_kind_name(const AreaLight&) { return "area"; }

/// What camera, mirror and refracted rays see of the light: its face (area_light_hit).
HIKARI_HD inline float face_hit(const AreaLight& light, Vec3 origin, Vec3 direction, float t_max) {
    return area_light_hit(light, origin, direction, t_max);
}
HIKARI_HD inline Vec3 face_radiance(const AreaLight& light) { return light.radiance; }
constexpr bool has_face(const AreaLight&) { return true; }

}  // namespace hikari
