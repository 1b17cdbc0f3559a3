#pragma once
// Whitted ray tracing: the lecture's Algorithm 4.3 plus shadow rays, mirror reflection and
// refraction (Whitted, "An Improved Illumination Model for Shaded Display", CACM 1980).

#include "hikari/frame/film.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/frame/render_settings.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// The ray tracer's own settings (`--spp`, `--max-depth`).
struct WhittedSettings {
    int samples_per_pixel = 1;  ///< 1: one ray through each pixel centre; more: stratified jitter
    int max_depth = 5;          ///< ray segments per path, the primary ray included
    bool shadow_rays = true;    ///< false: every light reaches every point facing it
    /// Stratified samples per area or environment light per shaded point (`--light-samples`).
    int light_samples = k_default_light_samples;
    /// Area lights' shadows in closed form (`--shadows analytic`) instead of by sampling.
    bool analytic_area_shadows = false;
};

/// `--method raytrace`: one ray per pixel centre (or stratified jittered samples), the nearest
/// hit shaded with the shared Phong model, lights tested with shadow rays, and
/// colour += reflectivity × trace(mirror ray) + transparency × trace(refracted ray),
/// up to whitted.max_depth ray segments per path. Writes every pixel of `film` (the camera's
/// size) and returns it with the AOVs.
Framebuffer render_whitted(const Scene& scene, Film film, const RenderSettings& settings = {},
                           const WhittedSettings& whitted = {});

}  // namespace hikari
