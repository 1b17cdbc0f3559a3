#pragma once
// The raster methods' own settings (zbuffer, scanline, depthsort, depthsort-naive).

#include <memory>

#include "hikari/core/simd_level.h"
#include "hikari/core/vec.h"
#include "hikari/frame/render_settings.h"

namespace hikari {

struct SharedShadowMaps;  // raster/shadow_map.h

/// How the raster methods interpolate shading across a triangle (the lecture's flat, Gouraud and
/// Phong shading).
enum class Interpolation {
    flat,     ///< one face normal per triangle
    gouraud,  ///< shade at the vertices, interpolate the colours
    phong,    ///< interpolate the normal, shade every pixel
};

/// Settings of the raster methods (`--interp`, `--cull`, `--shadows`, `--shadow-map-size`).
struct RasterSettings {
    Interpolation interp = Interpolation::phong;  ///< shading interpolation
    bool cull_back_faces = false;                 ///< drop triangles facing away (Fig 4.3)
    ShadowMode shadows = ShadowMode::none;        ///< none, map, volume, pcf, pcss or analytic
    int shadow_map_size = 2048;                   ///< texels per side of each shadow map face
    /// Samples of the specular term per area light and point (the diffuse term is analytic).
    int light_samples = k_default_light_samples;
    /// Where each pixel is sampled, relative to its centre, in pixels (each coordinate in
    /// [−½, ½)): the image is shifted so that pixel centres land there. The supersampling of
    /// `--spp` renders one pass per sub-pixel sample (frame/subpixel.h).
    Vec2 sample_offset{0.0f, 0.0f};
    /// Set by `--spp` supersampling: the shadow maps its passes share, drawn by the first pass
    /// that needs them (fitted to the shadow casters alone, so that they serve every pass).
    /// Null: each render draws its own.
    std::shared_ptr<SharedShadowMaps> shared_shadow_maps;
    /// `--paint-steps` (depthsort): paint only the first N polygons of the painting order, to
    /// watch the painter's algorithm of Fig 4.6 part-way; 0 paints them all.
    int paint_steps = 0;
    /// The SIMD kernels of the Z-buffer's tiles and of the shading lanes (every level gives the
    /// same image).
    SimdLevel simd = best_simd_level();
};

}  // namespace hikari
