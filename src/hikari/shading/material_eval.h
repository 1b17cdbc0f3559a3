#pragma once
// A material at a surface point, its texture applied once, for every method: the ray tracer
// (one hit, or a pack of hits) and the rasterizer's shading pass alike.

#include <cstdint>

#include "hikari/core/lanes.h"
#include "hikari/core/visit.h"
#include "hikari/scene/material.h"
#include "hikari/shading/material_sample.h"
#include "hikari/shading/phong.h"
#include "hikari/shading/surface.h"
#include "hikari/shading/texture.h"

namespace hikari {

namespace detail {
/// One material's coefficients at `point`, the same in every lane: its texture's colour scales
/// ka and kd. `scalar_only` is set when a pack meets a texture kind without a lane form.
template <class F>
HIKARI_INLINE HIKARI_HD MaterialSample<F> evaluate_one_material(const Material& m,
                                                                const SurfacePoint<F>& point) {
    MaterialSample<F> s;
    s.ka = Vec3T<F>(m.ka);
    s.kd = Vec3T<F>(m.kd);
    s.ks = Vec3T<F>(m.ks);
    const int32_t exponent = phong_integer_exponent(m.shininess);
    s.exponent = IntOf<F>(exponent);
    s.shininess = F(m.shininess);
    s.reflectivity = F(m.reflectivity);
    s.transparency = F(m.transparency);
    s.ior = F(m.ior);
    s.scalar_only = MaskOf<F>(!k_is_scalar<F> && exponent < 0);
    if (m.texture) {
        if (texture_has_lanes<F>(*m.texture)) {
            const Vec3T<F> c = texture_colour(*m.texture, point);
            if (!m.ambient_texture) s.ka = s.ka * c;
            s.kd = s.kd * c;
        } else {
            s.scalar_only = MaskOf<F>(true);
        }
    }
    if (m.vertex_colours) {
        // Only one-ray shading interpolates the colour (packs leave it white): packs go there.
        if constexpr (k_is_scalar<F>) {
            s.ka = s.ka * point.vertex_colour;
            s.kd = s.kd * point.vertex_colour;
        } else {
            s.scalar_only = MaskOf<F>(true);
        }
    }
    if (m.ambient_texture) {
        if (texture_has_lanes<F>(*m.ambient_texture))
            s.ka = s.ka * texture_colour(*m.ambient_texture, point);
        else
            s.scalar_only = MaskOf<F>(true);
    }
    return s;
}

template <class F>
HIKARI_INLINE HIKARI_HD void select_into(const MaskOf<F>& lanes, const MaterialSample<F>& a,
                                         MaterialSample<F>& out) {
    out.ka = select(lanes, a.ka, out.ka);
    out.kd = select(lanes, a.kd, out.kd);
    out.ks = select(lanes, a.ks, out.ks);
    out.exponent = select(lanes, a.exponent, out.exponent);
    out.shininess = select(lanes, a.shininess, out.shininess);
    out.reflectivity = select(lanes, a.reflectivity, out.reflectivity);
    out.transparency = select(lanes, a.transparency, out.transparency);
    out.ior = select(lanes, a.ior, out.ior);
    out.scalar_only = select(lanes, a.scalar_only, out.scalar_only);
}
}  // namespace detail

/// Material `index` of `materials` at `point` (each lane its own material, for a pack: each
/// material present is evaluated once over all lanes and kept where it belongs).
template <class F>
HIKARI_INLINE HIKARI_HD MaterialSample<F> evaluate_material(const Material* materials,
                                                            IntOf<F> index,
                                                            const SurfacePoint<F>& point) {
    if constexpr (k_is_scalar<F>) {
        return detail::evaluate_one_material<F>(materials[index], point);
    } else {
        MaterialSample<F> out;
        for_each_distinct(index, [&](int32_t m, const MaskOf<F>& lanes, bool first) {
            const MaterialSample<F> sample = detail::evaluate_one_material<F>(materials[m], point);
            // The first material fills every lane; the others overwrite theirs.
            if (first)
                out = sample;
            else
                detail::select_into<F>(lanes, sample, out);
        });
        return out;
    }
}

}  // namespace hikari
