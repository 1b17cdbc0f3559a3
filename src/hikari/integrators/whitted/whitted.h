#pragma once
// Whitted ray tracing: the lecture's Algorithm 4.3 plus shadow rays, mirror reflection and
// refraction (Whitted, "An Improved Illumination Model for Shaded Display", CACM 1980).

#include "hikari/frame/framebuffer.h"
#include "hikari/frame/render_settings.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// `--method raytrace`: one ray per pixel centre (or stratified jittered samples), the nearest
/// hit shaded with the shared Phong model, lights tested with shadow rays, and
/// colour += reflectivity × trace(mirror ray) + transparency × trace(refracted ray),
/// up to settings.max_depth ray segments per path.
Framebuffer render_whitted(const Scene& scene, const RenderSettings& settings);

}  // namespace hikari
