#pragma once
// The raster shading pass in SIMD lanes: the visible surface points of one tile, gathered as
// structure-of-arrays, lit by the shared shading code (shading/material_eval.h,
// shading/direct.h) on packs of the target's width, as the ray tracer's lanes are
// (integrators/whitted/whitted_shade.h). The packs run the same float operations as the
// one-point code, so every lane's colour is bit-identical to shading the point alone. Compiled
// three times (portable, AVX2, AVX-512) from shade_lanes_kernel.h and chosen at run time.

#include <cstddef>
#include <cstdint>

#include "hikari/core/simd_level.h"
#include "hikari/frame/tiles.h"
#include "hikari/scene/material.h"
#include "hikari/shading/lighting_environment.h"

namespace hikari {

/// Up to one tile's visible points, one array per quantity (lane k is point k). The shading
/// kernel reads the first round_up(count, k_lane_group) lanes: the caller fills the lanes past
/// `count` with a copy of a valid one.
struct alignas(64) SurfaceLanes {
    static constexpr int k_capacity = k_tile_size * k_tile_size;
    /// Lanes the kernels take at a time (AVX-512's sixteen floats).
    static constexpr int k_lane_group = 16;

    float position[3][k_capacity];  ///< world space
    float normal[3][k_capacity];    ///< unit shading normal facing the eye (also the geometric)
    float to_eye[3][k_capacity];    ///< unit direction toward the eye
    int32_t material[k_capacity];   ///< index into the scene's materials
    /// Texture coordinates and their per-pixel steps (SurfacePoint's fields).
    float u[k_capacity], v[k_capacity];
    float du_dx[k_capacity], dv_dx[k_capacity], du_dy[k_capacity], dv_dy[k_capacity];
    float dp_dx[3][k_capacity], dp_dy[3][k_capacity];
    /// Outputs: the lit colour, and 1 where the material has no lane form (a texture kind or
    /// vertex colours only the one-point code evaluates): that lane's colour must be redone.
    float colour[3][k_capacity];
    int32_t scalar_only[k_capacity];
};

/// What the lanes are lit by: the scene's lights and materials, and the caller's shadow answer.
struct LaneLighting {
    LightingEnvironment lighting;  ///< delta lights only (point, directional, spot)
    const Material* materials = nullptr;
    /// Writes into fraction[j] how much of light `light` reaches lane first + j, for every j
    /// whose bit is set in `lanes` (fraction[j] of the others is not read). Null: every light
    /// reaches every lane (1).
    void (*fractions)(const void* context, size_t light, int first, uint32_t lanes,
                      float* fraction) = nullptr;
    const void* context = nullptr;
};

namespace detail {
void shade_surface_lanes_portable(const LaneLighting& lighting, int count, SurfaceLanes& lanes);
void shade_surface_lanes_avx2(const LaneLighting& lighting, int count, SurfaceLanes& lanes);
void shade_surface_lanes_avx512(const LaneLighting& lighting, int count, SurfaceLanes& lanes);
}  // namespace detail

/// Lights lanes [0, count) of `lanes` (colour and scalar_only) with `level`'s kernel: ambient
/// plus every delta light of `lighting` the caller's fractions let through (shading/direct.h).
inline void shade_surface_lanes(const LaneLighting& lighting, int count, SurfaceLanes& lanes,
                                SimdLevel level = best_simd_level()) {
    simd_pick(level, detail::shade_surface_lanes_portable, detail::shade_surface_lanes_avx2,
              detail::shade_surface_lanes_avx512)(lighting, count, lanes);
}

}  // namespace hikari
