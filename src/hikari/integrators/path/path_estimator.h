#pragma once
// The pieces of the path tracer's estimator that its CPU loop (path_tracer.cpp) and its wavefront
// kernels (path_kernel.h) share, written once for both (HIKARI_HD): the multiple-importance
// weight, Russian roulette's start, the energy scale of a material, and each pixel's seed of its
// Sobol' sequence (so that both take the same samples).

#include <cstddef>
#include <cstdint>

#include "hikari/bvh/surface_hit.h"
#include "hikari/core/host_device.h"
#include "hikari/core/sobol.h"
#include "hikari/scene/material.h"
#include "hikari/shading/bsdf/scattering.h"

namespace hikari {

/// Bounces before Russian roulette may end a path.
inline constexpr int k_roulette_after = 3;

/// Veach's power heuristic (β = 2) for a sample drawn with density `a` against density `b`.
HIKARI_HD inline float power_heuristic(float a, float b) {
    const float a2 = a * a, b2 = b * b;
    return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

/// The factor that brings a material's lobes down to conserving energy (1 where they do).
inline float energy_scale(const Material& m) {
    const float total = scattered_fraction(m.kd, m.ks, m.reflectivity, m.transparency);
    return total > 1.0f ? 1.0f / total : 1.0f;
}

/// Where a path scatters at `hit`, met by a ray along `direction` on its `front` side: the
/// normals turned to the side the ray came from (the shading normal kept on the geometric
/// normal's side), and whether the ray enters the surface.
HIKARI_HD inline ScatterFrame scatter_frame_at(const SurfaceHit& hit, Vec3 direction, bool front) {
    ScatterFrame at;
    at.to_eye = -direction;
    at.entering = front;
    at.geometric_normal = front ? hit.geometric_normal : -hit.geometric_normal;
    at.normal = dot(hit.shading_normal, at.geometric_normal) < 0.0f ? -hit.shading_normal
                                                                    : hit.shading_normal;
    return at;
}

/// A pixel's seed: its index hashed, so neighbouring pixels' sequences are unrelated.
HIKARI_HD inline uint32_t pixel_seed(size_t pixel) {
    return hash_u32(static_cast<uint32_t>(pixel) ^ hash_u32(static_cast<uint32_t>(pixel >> 32)));
}

}  // namespace hikari
