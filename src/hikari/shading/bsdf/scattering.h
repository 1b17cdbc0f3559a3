#pragma once
// A scene material as light transport sees it (docs/path-tracing.md): a mixture of four lobes,
// each from the lecture's coefficients,
//   kd            Lambert diffuse, f = kd / π                        (shading/bsdf/lambert.h)
//   ks, n         normalized Phong, f = ks (n+2)/2π cos^n α          (normalized_phong.h)
//   reflectivity  a perfect mirror
//   transparency  a smooth dielectric of index `ior`: Fresnel-weighted mirror and refraction
// (dielectric.h). ka has no meaning here: the ambient term stood in for the light that the
// path tracer follows. The fraction of light the mixture reflects or transmits is at most
// max(kd + ks) + reflectivity + transparency, which must not exceed 1.
// One lobe is chosen per bounce with probability proportional to its weight; the diffuse and
// Phong lobes have densities (and are evaluated together, so their pdfs add: one-sample MIS
// between lobes), the mirror and the dielectric are deltas.

#include <algorithm>
#include <cstdint>

#include "hikari/core/host_device.h"
#include "hikari/core/vec.h"
#include "hikari/shading/bsdf/dielectric.h"
#include "hikari/shading/bsdf/lambert.h"
#include "hikari/shading/bsdf/normalized_phong.h"
#include "hikari/shading/material_sample.h"

namespace hikari {

/// Where a BSDF is evaluated: the direction back along the path and the surface's normals,
/// both turned to its side.
struct ScatterFrame {
    Vec3 to_eye;            ///< ω_o: unit, toward where the path came from
    Vec3 normal;            ///< shading normal, dot(normal, to_eye) ≥ 0 where possible
    Vec3 geometric_normal;  ///< the true normal, dot(geometric_normal, to_eye) > 0
    bool entering = true;   ///< the path arrives from outside the object (glass: n_i = 1)
};

/// One direction drawn from the BSDF.
struct ScatterSample {
    Vec3 direction;      ///< ω_i, unit
    Vec3 weight{0.0f};   ///< f·|cos θ_i| / pdf (the path's throughput factor); 0: no sample
    float pdf = 0;       ///< density of the smooth lobes at ω_i (0 for a delta lobe)
    bool delta = false;  ///< drawn from the mirror or the dielectric
};

/// The maximum fraction of light a material's lobes can send on: max over channels of
/// kd + ks, plus reflectivity and transparency (1 or less for an energy-conserving material).
HIKARI_HD inline float scattered_fraction(Vec3 kd, Vec3 ks, float reflectivity,
                                          float transparency) {
    return max_component(kd + ks) + reflectivity + transparency;
}

/// A material's lobes at one surface point.
class Scattering {
  public:
    /// The lobes of `m` (its texture applied), each weight multiplied by `scale` (1, or the
    /// factor that brings an energy-creating material down to 1).
    HIKARI_HD Scattering(const MaterialSample<float>& m, float scale)
        : m_kd(m.kd * scale),
          m_ks(m.ks * scale),
          m_n(m.shininess),
          m_exponent(m.exponent),
          m_mirror(m.reflectivity * scale),
          m_glass(m.transparency * scale),
          m_ior(m.ior) {
        const float w_diffuse = average(m_kd), w_phong = average(m_ks);
        const float total = w_diffuse + w_phong + m_mirror + m_glass;
        if (!(total > 0.0f)) return;
        m_p_diffuse = w_diffuse / total;
        m_p_phong = w_phong / total;
        m_p_mirror = m_mirror / total;
        m_p_glass = m_glass / total;
    }

    /// Whether no light leaves the surface.
    HIKARI_HD bool black() const {
        return m_p_diffuse + m_p_phong + m_p_mirror + m_p_glass == 0.0f;
    }
    /// Whether some lobe has a density (light sampling can then find its paths).
    HIKARI_HD bool smooth() const { return m_p_diffuse + m_p_phong > 0.0f; }

    /// f(ω_o, ω_i) of the smooth lobes and their combined sampling density at ω_i (pdf, per
    /// steradian). Zero where ω_i lies under the surface (by either normal).
    HIKARI_HD Vec3 evaluate(const ScatterFrame& at, Vec3 wi, float& pdf) const {
        pdf = 0.0f;
        const float cos_i = dot(at.normal, wi);
        if (!(cos_i > 0.0f) || !(dot(at.geometric_normal, wi) > 0.0f)) return Vec3(0.0f);
        Vec3 f(0.0f);
        if (m_p_diffuse > 0.0f) {
            f += lambert_brdf(m_kd);
            pdf += m_p_diffuse * cosine_hemisphere_pdf(cos_i);
        }
        if (m_p_phong > 0.0f) {
            const float power =
                phong_lobe_power(phong_lobe_axis(at.to_eye, at.normal), wi, m_exponent, m_n);
            f += normalized_phong_brdf(m_ks, m_n, power);
            pdf += m_p_phong * normalized_phong_pdf(m_n, power);
        }
        return f;
    }

    /// A direction for the random numbers `u_lobe` (which lobe; for the dielectric also
    /// reflection or refraction) and `u` (where in it).
    HIKARI_HD ScatterSample sample(const ScatterFrame& at, float u_lobe, Vec2 u) const {
        ScatterSample s;
        if (u_lobe < m_p_diffuse) {
            s.direction = cosine_hemisphere_direction(at.normal, u);
        } else if (u_lobe < m_p_diffuse + m_p_phong) {
            s.direction = normalized_phong_direction(phong_lobe_axis(at.to_eye, at.normal), m_n, u);
        } else if (u_lobe < m_p_diffuse + m_p_phong + m_p_mirror) {
            return delta_reflection(at, m_mirror / m_p_mirror);
        } else {
            const float first = m_p_diffuse + m_p_phong + m_p_mirror;
            return dielectric(at, std::min((u_lobe - first) / m_p_glass, 0.99999994f));
        }
        const Vec3 f = evaluate(at, s.direction, s.pdf);
        if (s.pdf > 0.0f) s.weight = f * (dot(at.normal, s.direction) / s.pdf);
        return s;
    }

  private:
    HIKARI_HD static float average(Vec3 c) { return (c.x + c.y + c.z) * (1.0f / 3.0f); }

    /// The mirror direction, carrying `weight`; none where it would leave under the surface.
    HIKARI_HD static ScatterSample delta_reflection(const ScatterFrame& at, float weight) {
        ScatterSample s;
        s.delta = true;
        // Renormalized: along a chain of mirrors the rounding of reflect() would compound.
        s.direction = normalize(reflect(-at.to_eye, at.normal));
        if (dot(at.geometric_normal, s.direction) > 0.0f) s.weight = Vec3(weight);
        return s;
    }

    /// The dielectric: reflected with probability F (Fresnel), else refracted; `u` chooses.
    /// Radiance crossing into a denser medium is compressed into a narrower cone: the refracted
    /// path carries (n_i / n_t)² (Veach 1997, §5.2).
    HIKARI_HD ScatterSample dielectric(const ScatterFrame& at, float u) const {
        const float eta = at.entering ? 1.0f / m_ior : m_ior;
        const float cos_i = std::max(0.0f, dot(at.to_eye, at.normal));
        float cos_t = 0.0f;
        const float reflectance = fresnel_dielectric(cos_i, eta, cos_t);
        const float weight = m_glass / m_p_glass;
        if (u < reflectance) return delta_reflection(at, weight);
        ScatterSample s;
        s.delta = true;
        s.direction = refracted_direction(at.to_eye, at.normal, eta, cos_t);
        if (dot(at.geometric_normal, s.direction) < 0.0f) s.weight = Vec3(weight * eta * eta);
        return s;
    }

    Vec3 m_kd, m_ks;
    float m_n;
    int32_t m_exponent;
    float m_mirror, m_glass, m_ior;
    float m_p_diffuse = 0, m_p_phong = 0, m_p_mirror = 0, m_p_glass = 0;
};

}  // namespace hikari
