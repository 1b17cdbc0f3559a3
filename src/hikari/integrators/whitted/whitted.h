#pragma once
// Whitted ray tracing: the lecture's Algorithm 4.3 plus shadow rays, mirror reflection and
// refraction (Whitted, "An Improved Illumination Model for Shaded Display", CACM 1980).

#include <vector>

#include "hikari/bvh/scene_intersector.h"
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

/// A shadow ray of a ray-tree node toward one point or directional light.
struct ShadowRayRecord {
    uint32_t light = 0;    ///< index into Scene::lights
    bool facing = false;   ///< the surface faces the light (else no shadow ray is needed)
    bool blocked = false;  ///< something lies between the point and the light
};

/// One ray of a pixel's Whitted ray tree (Alg 4.3), as the ray tracer traced it.
struct RayTreeNode {
    enum class Kind { camera, mirror, refracted };
    Kind kind = Kind::camera;
    int depth = 0;        ///< ray segments before it: 0 for the camera ray
    int parent = -1;      ///< index of the node that spawned it; -1 for the camera ray
    float weight = 1.0f;  ///< the parent's reflectivity or refraction weight for it
    Ray ray;
    bool hit = false;
    SurfaceHit surface;  ///< where it hit (when `hit`)
    /// Its own colour: the local illumination at the hit (ambient + the lights its shadow rays
    /// reach), or what it sees of the sky or a light.
    Vec3 local{0.0f};
    /// The colour it returns: local + weight × each child's total.
    Vec3 total{0.0f};
    std::vector<ShadowRayRecord> shadow_rays;  ///< toward each point or directional light
};

/// The ray tree of pixel (x, y)'s centre ray, breadth first (`hikari explain -m raytrace`): the
/// render's own tracer traces it, and each node records what that tracer computed. total of the
/// first node is the pixel's colour in a one-sample render.
std::vector<RayTreeNode> whitted_ray_tree(const Scene& scene, const WhittedSettings& whitted, int x,
                                          int y);

/// `--method raytrace`: one ray per pixel centre (or stratified jittered samples), the nearest
/// hit shaded with the shared Phong model, lights tested with shadow rays, and
/// colour += reflectivity × trace(mirror ray) + transparency × trace(refracted ray),
/// up to whitted.max_depth ray segments per path. Writes every pixel of `film` (the camera's
/// size) and returns it with the AOVs.
Framebuffer render_whitted(const Scene& scene, Film film, const RenderSettings& settings = {},
                           const WhittedSettings& whitted = {});

}  // namespace hikari
