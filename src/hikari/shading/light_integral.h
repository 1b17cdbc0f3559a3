#pragma once
// Area and environment lights integrated at a surface point, for every method: the lecture's
// reflection term summed over many samples of the light instead of one (its area light is "a
// set of point lights", its environment light "a set of directional lights").
//   Σ_k visible_k · I_k (kd cos α_k + ks cos^n γ_k) / N,   I_k = L(y_k) · cos θ′_k / (r_k² pdf_k)
// The samples are stratified over the light (core/strata.h) and drawn from a random stream
// seeded by the point and the light, so images are the same for any thread count.
// Two ways to integrate an area light are here: sampling, with the caller's visibility test per
// sample (shadow rays), and the analytic one (shading/soft_shadows/visible_light.h): the diffuse
// term in closed form over the visible part of the light, the specular term sampled over it.

#include <bit>
#include <concepts>
#include <cstddef>
#include <cstdint>

#include "hikari/core/rng.h"
#include "hikari/core/strata.h"
#include "hikari/scene/light.h"
#include "hikari/shading/lights.h"
#include "hikari/shading/material_sample.h"
#include "hikari/shading/phong.h"
#include "hikari/shading/soft_shadows/visible_light.h"
#include "hikari/shading/surface.h"

namespace hikari {

/// The random stream of light `light`'s samples at point `p`: a hash of the point's coordinates
/// (splitmix64's finalizer) and the light's index.
inline Pcg32 light_sample_stream(Vec3 p, size_t light) {
    uint64_t h = (static_cast<uint64_t>(std::bit_cast<uint32_t>(p.x)) << 32) ^
                 std::bit_cast<uint32_t>(p.y) ^
                 (static_cast<uint64_t>(std::bit_cast<uint32_t>(p.z)) * 0x9e3779b97f4a7c15ULL);
    h ^= h >> 30;
    h *= 0xbf58476d1ce4e5b9ULL;
    h ^= h >> 27;
    h *= 0x94d049bb133111ebULL;
    h ^= h >> 31;
    return Pcg32(h, light);
}

/// Samples a visibility test may answer together (one packet of shadow rays).
inline constexpr int k_light_sample_batch = 16;

/// A visibility test that can answer up to k_light_sample_batch samples of one light at once:
/// `visible.many(l, samples, count, s)` returns the mask of the unblocked ones.
template <class Visible>
concept BatchVisibility = requires(Visible& v, const LightSample* samples,
                                   const SurfacePoint<float>& s) {
    { v.many(size_t{0}, samples, 0, s) } -> std::convertible_to<uint32_t>;
};

/// Area and environment lights by sampling: `samples` stratified samples, each lighting the
/// point where `visible(l, sample, s, true)` says it is not blocked (the method's shadow test:
/// a shadow ray for the ray tracer; where the test can, k_light_sample_batch samples at a time:
/// their shadow rays share an origin, so they traverse the BVH well as one packet).
struct SampledLights {
    int samples = 1;

    template <class Visible>
    Vec3 operator()(size_t l, const Light& light, const SurfacePoint<float>& s,
                    const MaterialSample<float>& m, bool specular, Visible& visible,
                    int32_t& tested) const {
        StratifiedSquare pattern(samples, light_sample_stream(s.position, l));
        Vec3 sum(0.0f);
        LightSample batch[k_light_sample_batch];
        float cosines[k_light_sample_batch];
        int pending = 0;
        // The samples asked so far, in order: their light where visible.
        const auto flush = [&]() {
            uint32_t lit = 0;
            if constexpr (BatchVisibility<Visible>) {
                lit = visible.many(l, batch, pending, s);
            } else {
                for (int i = 0; i < pending; ++i)
                    lit |= visible(l, batch[i], s, true) ? 1u << i : 0u;
            }
            for (int i = 0; i < pending; ++i)
                if ((lit >> i) & 1u) sum += phong_reflected(m, s, batch[i], cosines[i], specular);
            pending = 0;
        };
        for (int k = 0; k < samples; ++k) {
            const LightSample sample =
                sample_light_at(light, s.position, s.normal, pattern.next(k));
            const float cos_alpha = dot(s.normal, sample.to_light);
            if (!(cos_alpha > 0.0f) || max_component(sample.irradiance) <= 0.0f) continue;
            ++tested;
            batch[pending] = sample;
            cosines[pending++] = cos_alpha;
            if (pending == k_light_sample_batch) flush();
        }
        flush();
        return sum / static_cast<float>(samples);
    }
};

/// An area light's reflection at `s` over the part `seen` of it the point sees: the diffuse term
/// kd·L·∫cos θ dω in closed form, the specular term from `samples` stratified samples of the
/// light, those outside `seen` left dark.
inline Vec3 area_light_reflection(const AreaLight& light, const VisibleLight& seen, size_t l,
                                  const SurfacePoint<float>& s, const MaterialSample<float>& m,
                                  bool specular, int samples) {
    Vec3 colour = m.kd * light.radiance * seen.cosine_solid_angle;
    if (!specular || seen.piece_count() == 0) return colour;
    StratifiedSquare pattern(samples, light_sample_stream(s.position, l));
    Vec3 highlight(0.0f);
    for (int k = 0; k < samples; ++k) {
        const Vec2 uv = pattern.next(k);
        const LightSample sample = sample_area_light<float>(light, s.position, uv.x, uv.y);
        if (!(dot(s.normal, sample.to_light) > 0.0f) || !seen.sees(uv)) continue;
        highlight += sample.irradiance * phong_specular(m, s, sample.to_light);
    }
    return colour + m.ks * highlight / static_cast<float>(samples);
}

/// Area lights analytically (`--shadows analytic`): the part of the light not hidden by
/// `occluders` (Nishita & Nakamae 1983), then area_light_reflection. Environment lights are
/// sampled as SampledLights does.
struct AnalyticAreaLights {
    int samples = 1;
    const OccluderSet* occluders = nullptr;

    template <class Visible>
    Vec3 operator()(size_t l, const Light& light, const SurfacePoint<float>& s,
                    const MaterialSample<float>& m, bool specular, Visible& visible,
                    int32_t& tested) const {
        if (const auto* area = light_as<AreaLight>(light)) {
            const VisibleLight seen =
                visible_light(*area, s.position, s.normal, s.geometric_normal, occluders);
            return area_light_reflection(*area, seen, l, s, m, specular, samples);
        }
        return SampledLights{samples}(l, light, s, m, specular, visible, tested);
    }
};

}  // namespace hikari
