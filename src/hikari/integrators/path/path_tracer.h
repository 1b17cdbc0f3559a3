#pragma once
// Global illumination by unidirectional path tracing (Kajiya 1986, "The Rendering Equation"):
// the lecture's 大域照明, the inter-reflection of indirect light that its ambient term only
// stands in for. Each sample follows one path from the camera, scattering at every surface by
// the material's BSDF (shading/bsdf/scattering.h); at each vertex one light is sampled (next-
// event estimation) and weighed against the BSDF's own sampling by multiple importance
// sampling (Veach 1997, power heuristic). Docs: docs/path-tracing.md.

#include <functional>
#include <string>
#include <vector>

#include "hikari/core/image.h"
#include "hikari/frame/film.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/frame/pixel_filter.h"
#include "hikari/frame/render_settings.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// The path tracer's own settings (`--spp`, `--max-depth`, `--clamp`, `--time-limit`,
/// `--progressive`, `--filter`, `--filter-width`).
struct PathSettings {
    /// Samples per pixel; with a time limit, the most it may take.
    int samples_per_pixel = 64;
    /// Bounces: a path scatters at most this many times after its first hit (0: direct light
    /// only); light is sampled at every vertex, the last included.
    int max_depth = 8;
    /// A sample's radiance is scaled down to at most this in every channel (0: never; any
    /// other value biases the image to remove fireflies).
    float clamp = 0.0f;
    /// Caustic paths from emissive triangles traced from the lights (caustic_light_tracer.h);
    /// false: left to the camera paths (the same mean, far more noise).
    bool light_traced_caustics = true;
    /// Stop once this many seconds of rendering are spent (0: no limit); at least one sample
    /// per pixel is always taken.
    float time_limit_seconds = 0.0f;
    /// Call `snapshot` about every this many seconds with the image so far (0: never).
    float progressive_seconds = 0.0f;
    /// Receives the mean of the samples so far (linear RGB) and their count per pixel.
    std::function<void(const Image& mean, int samples)> snapshot;
    PixelFilterKind filter = PixelFilterKind::box;
    float filter_width = 0.0f;  ///< pixels; 0: the filter's default width
};

/// `--method path`: path-traced global illumination. Pixel (x, y)'s samples come from its own
/// scrambled Sobol' sequence (core/sobol.h), so the image is the same for any thread count.
Framebuffer render_path(const Scene& scene, Film film, const RenderSettings& settings = {},
                        const PathSettings& path = {});

/// What the path tracer says about `scene` before rendering: each material whose lobes would
/// reflect more light than they receive (kd + ks + reflectivity + transparency above 1 in some
/// channel), which it scales down to 1.
std::vector<std::string> path_scene_warnings(const Scene& scene);

}  // namespace hikari
