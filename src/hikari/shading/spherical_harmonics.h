#pragma once
// Environment light as the rasterizer shades it: the irradiance E(n) = ∫ L(ω) max(0, n·ω) dω
// of an environment, for every normal n, from nine spherical-harmonic coefficients of L
// (Ramamoorthi & Hanrahan 2001, "An Efficient Representation for Irradiance Environment Maps"):
// the clamped cosine is so smooth that bands 0 to 2 hold all but about 1% of E. The lookup is
// unshadowed: nothing between the point and the sky is asked.

#include <array>

#include "hikari/core/vec.h"
#include "hikari/scene/light.h"

namespace hikari {

/// An environment's radiance projected onto the real spherical harmonics of bands 0–2.
struct IrradianceSh {
    /// L_lm in the order (0,0), (1,−1), (1,0), (1,1), (2,−2), (2,−1), (2,0), (2,1), (2,2).
    std::array<Vec3, 9> coefficients{};

    /// E(n) for unit normal `n`: Σ Â_l L_lm Y_lm(n), Â_0 = π, Â_1 = 2π/3, Â_2 = π/4 (clamped
    /// at 0, where the truncation would ring below it).
    Vec3 irradiance(Vec3 n) const;
};

/// The nine real spherical harmonics Y_lm at unit direction `d`, in IrradianceSh's order.
std::array<float, 9> sh_basis(Vec3 d);

/// The coefficients of `light`'s radiance: exact for a constant one, summed over the texels of
/// a map (each texel's radiance times the solid angle it covers).
IrradianceSh project_environment(const EnvironmentLight& light);

}  // namespace hikari
