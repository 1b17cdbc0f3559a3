#pragma once
// The raster methods' own settings (zbuffer, scanline, depthsort, depthsort-naive).

#include <memory>

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
};

}  // namespace hikari
