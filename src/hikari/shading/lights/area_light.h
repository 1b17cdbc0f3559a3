#pragma once
// The area light's sampling routines. Every patch dA of the parallelogram is a point light of
// intensity L·cos θ′·dA, so a point p receives from it
//   E = ∫ L·cos θ′ / r² dA      (r = |y − p|, θ′ between the light's normal and p − y)
// times the lecture's reflection term. Sampled uniformly over the area (pdf 1/A), one sample
// y is a point light of irradiance L·A·cos θ′ / r² at p; the light seen from far away is that
// point light at its centre.

#include <cmath>

#include "hikari/core/lanes.h"
#include "hikari/core/vec.h"
#include "hikari/scene/light.h"
#include "hikari/shading/light_sample.h"

namespace hikari {

/// The light of `light` toward `p` from the light's point corner + u.x·edge1 + u.y·edge2,
/// weighted by 1 / pdf = A: irradiance L·A·cos θ′ / r², zero where p is behind a one-sided
/// light.
template <class F>
HIKARI_INLINE LightSampleT<F> sample_area_light(const AreaLight& light, const Vec3T<F>& p,
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
inline float area_light_hit(const AreaLight& light, Vec3 origin, Vec3 direction, float t_max) {
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
HIKARI_INLINE LightSampleT<F> sample_light(const AreaLight& light, const Vec3T<F>& p) {
    return sample_area_light<F>(light, p, F(0.5f), F(0.5f));
}

}  // namespace hikari
