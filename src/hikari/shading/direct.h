#pragma once
// Direct illumination, written once for every method (the lecture's Fig 4.29 summed over the
// lights): ambient, then each light that faces the point and that a visibility test lets
// through. The test is the caller's: the ray tracer passes shadow rays (Alg 4.3's shadow
// test), the rasterizer shadow-map or shadow-volume lookups. Area and environment lights are
// integrated over many samples by the caller's `extended` policy (shading/light_integral.h).

#include <cstddef>
#include <type_traits>

#include "hikari/core/lanes.h"
#include "hikari/core/vec.h"
#include "hikari/scene/light.h"
#include "hikari/shading/light_integral.h"
#include "hikari/shading/lighting_environment.h"
#include "hikari/shading/lights.h"
#include "hikari/shading/material_sample.h"
#include "hikari/shading/phong.h"
#include "hikari/shading/surface.h"

namespace hikari {

/// What direct_lighting found.
template <class F>
struct DirectLighting {
    Vec3T<F> colour;    ///< ka Ia + Σ over visible lights of the Phong reflection
    IntOf<F> tested{};  ///< lights facing the point: visibility tests asked (shadow rays)
};

/// ka Ia + Σ_l visible_l · I_l (kd cos α + ks cos^n γ) at `s` for the lanes in `active`.
/// `visible(l, sample, s, facing)` answers, for the lanes in `facing` (where light l's
/// cos α > 0), whether light l reaches the point unblocked (or, for one point, which fraction
/// of it does, as a float); it is called only where some lane
/// faces the light. Area and environment lights add
/// `extended(l, light, s, m, specular, visible, tested)` (SampledLights by default: each sample
/// asks `visible`); they are shaded one point at a time, and packs of lanes never meet them (the
/// ray tracer shades the hits of scenes that have them one ray at a time).
template <class F, class Visible, class Extended = SampledLights>
HIKARI_INLINE HIKARI_HD DirectLighting<F> direct_lighting(
    const LightingEnvironment& env, const SurfacePoint<F>& s, const MaterialSample<F>& m,
    const MaskOf<F>& active, Visible&& visible, const Extended& extended = {}) {
    DirectLighting<F> out{m.ka * Vec3T<F>(env.ambient), IntOf<F>(0)};
    // Skipping the highlight where no lane is shiny changes no bit (ks · anything = 0).
    const MaskOf<F> shiny = (m.ks.x != F(0.0f)) | (m.ks.y != F(0.0f)) | (m.ks.z != F(0.0f));
    const bool specular = any(active & shiny);
    for (size_t l = 0; l < env.light_count; ++l) {
        if (!is_delta_light(env.lights[l])) {
            if constexpr (k_is_scalar<F>)
                if (active)
                    out.colour += extended(l, env.lights[l], s, m, specular, visible, out.tested);
            continue;
        }
        const LightSampleT<F> light = sample_light<F>(env.lights[l], s.position);
        const F cos_alpha = dot(s.normal, light.to_light);
        const MaskOf<F> facing = active & !(cos_alpha <= F(0.0f));
        if (!any(facing)) continue;
        out.tested += mask_to_int(facing);
        const auto reach = visible(l, light, s, facing);
        if constexpr (std::is_same_v<std::decay_t<decltype(reach)>, float>) {
            // A fraction of the light gets through (filtered shadow maps); one point only.
            if (!(reach > 0.0f)) continue;
            out.colour = out.colour + phong_reflected(m, s, light, cos_alpha, specular) * reach;
        } else if constexpr (std::is_same_v<std::decay_t<decltype(reach)>, F>) {
            // The same per lane (the raster shading pass's lanes): lane for lane what one point
            // gets.
            const MaskOf<F> lit = facing & (reach > F(0.0f));
            if (!any(lit)) continue;
            out.colour =
                select(lit, out.colour + phong_reflected(m, s, light, cos_alpha, specular) * reach,
                       out.colour);
        } else {
            const MaskOf<F> lit = facing & reach;
            if (!any(lit)) continue;
            out.colour = select(lit, out.colour + phong_reflected(m, s, light, cos_alpha, specular),
                                out.colour);
        }
    }
    return out;
}

}  // namespace hikari
