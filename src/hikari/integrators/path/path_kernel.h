#pragma once
// The path tracer as a wavefront integrator (Laine, Karras & Aila 2013, "Megakernels Considered
// Harmful: Wavefront Path Tracing on GPUs"; pbrt-v4's GPU integrator): instead of one thread
// following a path from the camera to its end, each stage of a bounce is its own kernel over a
// queue of paths, so that the GPU's threads run the same code side by side:
//   1. camera rays      one per pixel-sample, into the ray queue (GenerateCameraRays)
//   2. nearest hits     of the queue's rays through the wide BVH (IntersectRays)
//   3. shading          light met, next-event estimation into the shadow queue, the BSDF's
//                       next direction into the next bounce's ray queue (ShadePaths)
//   4. shadow rays      any-hit tests adding the light samples that arrive (TraceShadowRays)
// then 2–4 again on the next queue until it is empty, and each pixel's samples summed in order
// (ResolvePixels). The estimator is render_path's (path_tracer.cpp), step for step and from the
// same shared code (bvh/flat_intersector.h, shading/bsdf, shading/lights, EmitterView, the same
// Sobol' samples per pixel), so the CPU run of these kernels gives render_path's image.
//
// Determinism: queue slots are taken atomically (core/device_atomic.h), so their order varies
// with the threads; every entry names its path, and each path owns its state and its radiance,
// so nothing computed depends on that order (no float atomics into pixels).

#include <cstddef>
#include <cstdint>

#include "hikari/bvh/flat_intersector.h"
#include "hikari/core/device_atomic.h"
#include "hikari/core/flat_view.h"
#include "hikari/core/host_device.h"
#include "hikari/core/sobol.h"
#include "hikari/frame/pixel_filter.h"
#include "hikari/geometry/ray_offset.h"
#include "hikari/integrators/path/emitters.h"
#include "hikari/integrators/path/path_estimator.h"
#include "hikari/scene/camera.h"
#include "hikari/scene/scene.h"
#include "hikari/shading/bsdf/scattering.h"
#include "hikari/shading/lights.h"
#include "hikari/shading/material_eval.h"

namespace hikari {

/// One path of a wave, between its kernels.
struct PathState {
    Ray ray;                 ///< the ray to trace next
    Vec3 throughput{1.0f};   ///< the product of the BSDF weights so far
    Vec3 radiance{0.0f};     ///< the light the path has gathered
    Vec3 last_normal{0.0f};  ///< the shading normal of the last bounce (MIS of light met)
    SobolSampler sampler{0, 0};
    float bsdf_pdf = 0;    ///< the density of the last bounce's direction (0: delta)
    int32_t bounce = 0;    ///< scattering events so far
    bool specular = true;  ///< camera ray, or after a delta bounce: light met counts fully
};

/// A shadow ray of next-event estimation: what it adds to its path when nothing blocks it.
struct ShadowRay {
    uint32_t path = 0;
    Ray ray;
    float t_max = 0;
    Vec3 contribution{0.0f};  ///< throughput × f × L × cos θ × w / pdf
};

/// What every kernel of a wave reads: the scene as flat views and the wave's own arrays.
/// A wave is `samples` consecutive samples (from `first_sample`) of every pixel; its path
/// `pixel × samples + j` is sample first_sample + j of that pixel.
struct PathWave {
    FlatIntersector scene;
    EmitterView emitters;
    FlatView<Light> lights;
    const Material* materials = nullptr;
    const float* scale = nullptr;  ///< energy_scale of each material
    const Sky* sky = nullptr;
    Vec3 background{0.0f};
    const EnvironmentLight* environment = nullptr;  ///< the scene's, constant (maps are refused)
    bool has_area_lights = false;

    CameraFrame frame;
    const float* filter_inverse_cdf = nullptr;  ///< PixelFilter::inverse_cdf, null: the box
    float filter_width = 1.0f;
    int max_depth = 8;
    float clamp = 0.0f;

    uint32_t first_sample = 0;
    uint32_t samples = 1;  ///< per pixel in this wave
    PathState* paths = nullptr;
    SurfaceHit* hits = nullptr;  ///< each path's nearest hit (HitKind::none: none)
};

/// Stage 1: path i's camera ray through the point render_path's pixel filter draws for it, the
/// path started, and i into the ray queue (all paths, in order).
struct GenerateCameraRays {
    PathWave wave;
    uint32_t* queue = nullptr;

    HIKARI_HD void operator()(size_t i) const {
        const size_t pixel = i / wave.samples;
        const uint32_t s = wave.first_sample + static_cast<uint32_t>(i % wave.samples);
        const int x = static_cast<int>(pixel % static_cast<size_t>(wave.frame.width));
        const int y = static_cast<int>(pixel / static_cast<size_t>(wave.frame.width));
        PathState path;
        path.sampler = SobolSampler(pixel_seed(pixel), s);
        const Vec2 u = path.sampler.next_2d();
        const Vec2 offset{filter_offset_1d(wave.filter_inverse_cdf, wave.filter_width, u.x),
                          filter_offset_1d(wave.filter_inverse_cdf, wave.filter_width, u.y)};
        path.ray = camera_ray(wave.frame, static_cast<float>(x) + 0.5f + offset.x,
                              static_cast<float>(y) + 0.5f + offset.y);
        wave.paths[i] = path;
        queue[i] = static_cast<uint32_t>(i);
    }
};

/// Stage 2: the nearest hit of each queued path's ray.
struct IntersectRays {
    PathWave wave;
    const uint32_t* queue = nullptr;

    HIKARI_HD void operator()(size_t i) const {
        const uint32_t p = queue[i];
        SurfaceHit hit;
        if (!wave.scene.closest(wave.paths[p].ray, {0.0f, k_infinity}, hit))
            hit.kind = HitKind::none;
        wave.hits[p] = hit;
    }
};

/// Stage 3: one vertex of each queued path, as one pass of render_path's bounce loop: the light
/// its ray met (an area light's face, the sky, an emitter, weighed by MIS after a smooth
/// bounce), a light sample into the shadow queue, and the BSDF's next ray into `next` unless
/// the path ends there (black surface, max depth, no direction, Russian roulette).
struct ShadePaths {
    PathWave wave;
    const uint32_t* queue = nullptr;
    uint32_t* next = nullptr;
    uint32_t* next_count = nullptr;
    ShadowRay* shadows = nullptr;
    uint32_t* shadow_count = nullptr;

    HIKARI_HD void operator()(size_t i) const {
        const uint32_t p = queue[i];
        PathState& path = wave.paths[p];
        const SurfaceHit& hit = wave.hits[p];
        const bool found = hit.kind != HitKind::none;
        const Ray& ray = path.ray;
        /* light met: an area light's face nearer than the hit, or the sky */
        if (wave.has_area_lights) {
            LightFaceHit face;
            if (find_light_face(wave.lights.data, wave.lights.size(), ray.origin, ray.direction,
                                found ? hit.t : k_infinity, face)) {
                const float w =
                    path.specular ? 1.0f
                                  : power_heuristic(path.bsdf_pdf, wave.emitters.light_pdf(
                                                                       face.light, path.last_normal,
                                                                       ray.direction, face.t));
                path.radiance += path.throughput * face_radiance(wave.lights[face.light]) * w;
                return;
            }
        }
        if (!found) {
            path.radiance += path.throughput * escaped(path, ray.direction);
            return;
        }
        /* an emitter's own light */
        const Material& material = wave.materials[hit.material];
        const bool front = dot(hit.geometric_normal, ray.direction) < 0.0f;
        if (front && max_component(material.emission) > 0.0f) {
            const float light_pdf =
                hit.kind == HitKind::triangle
                    ? wave.emitters.triangle_pdf(hit.index, ray.direction, hit.t)
                    : 0.0f;
            path.radiance += path.throughput * material.emission *
                             (path.specular ? 1.0f : power_heuristic(path.bsdf_pdf, light_pdf));
        }
        // The vertex's random numbers, drawn whether used or not (render_path's order).
        const float u_choice = path.sampler.next_1d();
        const Vec2 u_light = path.sampler.next_2d();
        const float u_lobe = path.sampler.next_1d();
        const Vec2 u_direction = path.sampler.next_2d();
        const float u_roulette = path.sampler.next_1d();

        const ScatterFrame at = scatter_frame_at(hit, ray.direction, front);
        const Scattering bsdf(material_at(hit, at), wave.scale[hit.material]);
        if (bsdf.black()) return;
        /* next-event estimation: a shadow ray for stage 4 */
        if (bsdf.smooth() && !wave.emitters.empty())
            queue_light_sample(p, path, hit.position, at, bsdf, u_choice, u_light);
        if (path.bounce >= wave.max_depth) return;
        /* the BSDF's next direction */
        const ScatterSample scattered = bsdf.sample(at, u_lobe, u_direction);
        if (!(max_component(scattered.weight) > 0.0f)) return;
        path.throughput = path.throughput * scattered.weight;
        path.specular = scattered.delta;
        path.bsdf_pdf = scattered.pdf;
        path.last_normal = at.normal;
        if (path.bounce + 1 >= k_roulette_after) {
            // Russian roulette: continue with probability q, carrying 1/q (unbiased).
            const float q = std::min(1.0f, max_component(path.throughput));
            if (!(u_roulette < q)) return;
            path.throughput = path.throughput / q;
        }
        const Vec3 side = dot(scattered.direction, at.geometric_normal) > 0.0f
                              ? at.geometric_normal
                              : -at.geometric_normal;
        path.ray = {offset_ray_origin(hit.position, side), scattered.direction};
        ++path.bounce;
        next[atomic_increment(next_count)] = p;
    }

    /// What a ray that leaves the scene along `dir` brings back (render_path's escaped): the
    /// environment light, weighed against light sampling after a smooth bounce, else, for
    /// camera rays and mirror chains, the backdrop (which lights nothing).
    HIKARI_HD Vec3 escaped(const PathState& path, Vec3 dir) const {
        if (wave.environment) {
            const float w = path.specular
                                ? 1.0f
                                : power_heuristic(path.bsdf_pdf, wave.emitters.environment_pdf(
                                                                     dir, path.last_normal));
            // A constant environment's radiance_from(dir): its radiance.
            return wave.environment->radiance * w;
        }
        return path.specular ? wave.sky->colour(dir, wave.background) : Vec3(0.0f);
    }

    /// The material at `hit`, its checker texture and vertex colours applied (material_at_hit).
    HIKARI_HD MaterialSample<float> material_at(const SurfaceHit& hit,
                                                const ScatterFrame& at) const {
        SurfacePoint<float> point{hit.position, at.normal, at.geometric_normal, at.to_eye};
        const Material& m = wave.materials[hit.material];
        if (m.texture || m.ambient_texture) {
            const SurfaceUv uv = surface_uv_of(wave.scene.geometry, hit);
            point.u = uv.uv.x, point.v = uv.uv.y;
        }
        if (m.vertex_colours) point.vertex_colour = surface_colour_of(wave.scene.geometry, hit);
        return evaluate_material<float>(wave.materials, static_cast<int32_t>(hit.material), point);
    }

    /// Next-event estimation at `x` (render_path's light_sample up to its shadow ray): one
    /// emitter sample weighed by MIS, queued with its shadow ray when it can carry light.
    HIKARI_HD void queue_light_sample(uint32_t p, const PathState& path, Vec3 x,
                                      const ScatterFrame& at, const Scattering& bsdf,
                                      float u_choice, Vec2 u) const {
        const EmitterSample light = wave.emitters.sample(x, at.normal, u_choice, u);
        if (!(light.pdf > 0.0f) || !(max_component(light.radiance) > 0.0f)) return;
        float bsdf_pdf = 0.0f;
        const Vec3 f = bsdf.evaluate(at, light.to_light, bsdf_pdf);
        if (!(max_component(f) > 0.0f)) return;
        // Stop just short of a sampled surface point, or the light's own face would block it.
        const float t_max =
            std::isinf(light.distance) ? k_infinity : light.distance * (1.0f - 1e-4f);
        const float w = light.delta ? 1.0f : power_heuristic(light.pdf, bsdf_pdf);
        ShadowRay& shadow = shadows[atomic_increment(shadow_count)];
        shadow.path = p;
        shadow.ray = {offset_ray_origin(x, at.geometric_normal), light.to_light};
        shadow.t_max = t_max;
        shadow.contribution = path.throughput * (f * light.radiance *
                                                 (dot(at.normal, light.to_light) * w / light.pdf));
    }
};

/// Stage 4: each queued shadow ray's light added to its path where nothing blocks it. A path
/// queues at most one shadow ray per bounce, so no two threads add to the same path.
struct TraceShadowRays {
    PathWave wave;
    const ShadowRay* shadows = nullptr;

    HIKARI_HD void operator()(size_t i) const {
        const ShadowRay& shadow = shadows[i];
        if (!wave.scene.occluded(shadow.ray, {0.0f, shadow.t_max}))
            wave.paths[shadow.path].radiance += shadow.contribution;
    }
};

/// The last step of a wave, per pixel: its paths' radiance (clamped as render_path clamps a
/// sample, non-finite samples dropped and counted) added to the pixel's sum in sample order,
/// the order render_path adds them in.
struct ResolvePixels {
    PathWave wave;
    Vec3* sums = nullptr;
    uint32_t* bad_samples = nullptr;  ///< per pixel

    HIKARI_HD void operator()(size_t pixel) const {
        Vec3 sum = sums[pixel];
        for (uint32_t j = 0; j < wave.samples; ++j) {
            Vec3 value = wave.paths[pixel * wave.samples + j].radiance;
            if (wave.clamp > 0.0f) {
                const float peak = max_component(value);
                if (peak > wave.clamp) value = value * (wave.clamp / peak);
            }
            if (is_finite(value))
                sum += value;
            else
                ++bad_samples[pixel];
        }
        sums[pixel] = sum;
    }
};

/// The first hit of the ray through each pixel's centre (the AOVs, as render_path stores them).
struct PixelCentreHits {
    FlatIntersector scene;
    CameraFrame frame;
    SurfaceHit* hits = nullptr;

    HIKARI_HD void operator()(size_t i) const {
        const int x = static_cast<int>(i % static_cast<size_t>(frame.width));
        const int y = static_cast<int>(i / static_cast<size_t>(frame.width));
        const Ray ray =
            camera_ray(frame, static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
        SurfaceHit hit;
        if (!scene.closest(ray, {0.0f, k_infinity}, hit)) hit.kind = HitKind::none;
        hits[i] = hit;
    }
};

/// Each kernel over [0, count) on `device` (core/device_launch.h); their own file,
/// path_kernel_launch.cpp, which nvcc compiles when HIKARI_CUDA is on.
void launch_path_kernel(ExecutionDevice device, size_t count, const GenerateCameraRays& kernel);
void launch_path_kernel(ExecutionDevice device, size_t count, const IntersectRays& kernel);
void launch_path_kernel(ExecutionDevice device, size_t count, const ShadePaths& kernel);
void launch_path_kernel(ExecutionDevice device, size_t count, const TraceShadowRays& kernel);
void launch_path_kernel(ExecutionDevice device, size_t count, const ResolvePixels& kernel);
void launch_path_kernel(ExecutionDevice device, size_t count, const PixelCentreHits& kernel);

}  // namespace hikari
