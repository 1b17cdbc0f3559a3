#pragma once
// What Whitted ray tracing does at a hit (Whitted 1980; the lecture's Alg 4.3 and Fig 4.43),
// written once over the number type: the one-ray path and the SIMD lanes of a block of rays
// (whitted_shade_kernel.h) run this same source.
//   1. turn the normals toward the incoming ray (planes and triangles are two-sided; a ray inside
//      a sphere sees its inner side);
//   2. evaluate the material there (shading/material_eval.h) and light it directly
//      (shading/direct.h) with the caller's shadow test;
//   3. spawn the mirror ray and the refracted ray (Snell's law), with POV-Ray's rule for total
//      internal reflection.

#include "hikari/core/lanes.h"
#include "hikari/core/vec.h"
#include "hikari/geometry/ray_offset.h"
#include "hikari/integrators/whitted/whitted_scene.h"
#include "hikari/scene/material.h"
#include "hikari/scene/scene.h"
#include "hikari/shading/direct.h"
#include "hikari/shading/material_eval.h"
#include "hikari/shading/refraction.h"
#include "hikari/shading/surface.h"

namespace hikari {

/// A ray's nearest hit as shading reads it (SurfaceHit's fields, for one ray or each lane's).
template <class F>
struct WhittedHit {
    Vec3T<F> direction;         ///< the ray's unit direction
    Vec3T<F> position;          ///< world space
    Vec3T<F> geometric_normal;  ///< unit, as the primitive defines it (not turned)
    Vec3T<F> shading_normal;    ///< unit, interpolated for meshes
    IntOf<F> material{};        ///< index into Scene::materials
    /// Texture coordinates and the pixel's footprint in texture space (SurfacePoint's fields;
    /// the ray tracer's one-ray path fills them from ray cones, the lanes leave them 0).
    F u = F(0.0f), v = F(0.0f);
    F du_dx = F(0.0f), dv_dx = F(0.0f), du_dy = F(0.0f), dv_dy = F(0.0f);
    Vec3T<F> dp_dx = Vec3T<F>(F(0.0f)), dp_dy = Vec3T<F>(F(0.0f));
    /// The vertex colour (SurfacePoint's; the one-ray path fills it, the lanes leave it white).
    Vec3T<F> vertex_colour = Vec3T<F>(F(1.0f));
};

/// A shaded hit: the point as shading saw it, its material and its direct light.
template <class F>
struct WhittedShading {
    SurfacePoint<F> point;  ///< normals turned toward the ray
    MaskOf<F> entering{};   ///< the ray meets the geometric normal's front side
    MaterialSample<F> material;
    DirectLighting<F> direct;  ///< the local colour and the shadow rays it cast
};

/// Step 1: the hit as a surface point with its normals facing the ray; a shading normal
/// interpolated to face away falls back to the geometric one.
template <class F>
HIKARI_INLINE HIKARI_HD SurfacePoint<F> face_the_ray(const WhittedHit<F>& hit,
                                                     MaskOf<F>& entering) {
    entering = dot(hit.geometric_normal, hit.direction) < F(0.0f);
    SurfacePoint<F> s;
    s.position = hit.position;
    s.geometric_normal = select(entering, hit.geometric_normal, -hit.geometric_normal);
    const Vec3T<F> n = select(entering, hit.shading_normal, -hit.shading_normal);
    s.normal = select(dot(n, hit.direction) > F(0.0f), s.geometric_normal, n);
    s.to_eye = -hit.direction;
    s.u = hit.u, s.v = hit.v;
    s.du_dx = hit.du_dx, s.dv_dx = hit.dv_dx, s.du_dy = hit.du_dy, s.dv_dy = hit.dv_dy;
    s.dp_dx = hit.dp_dx, s.dp_dy = hit.dp_dy;
    s.vertex_colour = hit.vertex_colour;
    return s;
}

/// Steps 1 and 2 for the lanes in `active`: the local illumination of the hit, area and
/// environment lights integrated by `extended` (shading/direct.h). `visible` is direct_lighting's
/// shadow test; shadow rays leave from offset_ray_origin(position, point.geometric_normal).
template <class F, class Visible, class Extended>
HIKARI_INLINE HIKARI_HD WhittedShading<F> shade_whitted_hit(const WhittedScene& scene,
                                                            const WhittedHit<F>& hit,
                                                            const MaskOf<F>& active,
                                                            Visible&& visible,
                                                            const Extended& extended) {
    WhittedShading<F> out;
    out.point = face_the_ray(hit, out.entering);
    out.material = evaluate_material<F>(scene.materials, hit.material, out.point);
    out.direct =
        direct_lighting<F>(scene.lighting, out.point, out.material, active, visible, extended);
    return out;
}

/// Steps 1 and 2 with the scene's way of integrating area lights: sampled, or in closed form
/// over the occluders where the scene has them (`--shadows analytic`).
template <class F, class Visible>
HIKARI_INLINE WhittedShading<F> shade_whitted_hit(const WhittedScene& scene,
                                                  const WhittedHit<F>& hit, const MaskOf<F>& active,
                                                  Visible&& visible) {
    if (scene.occluders)
        return shade_whitted_hit<F>(scene, hit, active, visible,
                                    AnalyticAreaLights{scene.light_samples, scene.occluders});
    return shade_whitted_hit<F>(scene, hit, active, visible, SampledLights{scene.light_samples});
}

/// The secondary rays of a hit; a weight of 0 means no such ray.
template <class F>
struct SecondaryRays {
    F mirror_weight = F(0.0f), refract_weight = F(0.0f);
    Vec3T<F> mirror_origin, mirror_direction;
    Vec3T<F> refract_origin, refract_direction;
};

/// Step 3 for the lanes in `active`: colour += mirror_weight × trace(mirror ray) +
/// refract_weight × trace(refracted ray). On total internal reflection the mirror ray takes the
/// transmitted weight and the reflectivity term is dropped (POV-Ray's rule), so the mirror ray
/// is traced once.
template <class F>
HIKARI_INLINE HIKARI_HD SecondaryRays<F> whitted_secondary_rays(const WhittedShading<F>& shaded,
                                                                const Vec3T<F>& direction,
                                                                const MaskOf<F>& active) {
    const MaterialSample<F>& m = shaded.material;
    const SurfacePoint<F>& s = shaded.point;
    const MaskOf<F> transparent = active & (m.transparency > F(0.0f));
    const MaskOf<F> reflective = active & (m.reflectivity > F(0.0f));
    SecondaryRays<F> rays;
    if (!any(transparent | reflective)) return rays;
    // Renormalized: reflect() keeps unit length only up to rounding, and a ray trapped by total
    // internal reflection is reflected again and again, each time from a direction a little
    // off unit length; the sphere and plane tests take the direction as unit, so the drift
    // (about 1e-7 per bounce) would compound until the ray left the sphere.
    const Vec3T<F> mirror = reflect(direction, s.normal);
    rays.mirror_direction = mirror * (F(1.0f) / sqrt_of(dot(mirror, mirror)));
    rays.mirror_origin = offset_ray_origin(s.position, s.geometric_normal);
    if (!any(transparent)) {
        rays.mirror_weight = select(active, m.reflectivity, F(0.0f));
        return rays;
    }
    const F eta = select(shaded.entering, F(1.0f) / m.ior, m.ior);
    const Refraction<F> refracted = refract_ray(direction, s.normal, eta);
    rays.refract_direction = refracted.direction;
    rays.refract_origin = offset_ray_origin(s.position, -s.geometric_normal);
    const MaskOf<F> total_internal = transparent & refracted.total_internal;
    rays.mirror_weight =
        select(active, select(total_internal, m.transparency, m.reflectivity), F(0.0f));
    rays.refract_weight = select(transparent & !refracted.total_internal, m.transparency, F(0.0f));
    return rays;
}

}  // namespace hikari
