#include "hikari/integrators/path/path_kernels.h"

#include <algorithm>
#include <optional>
#include <span>
#include <utility>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "hikari/bvh/scene_intersector.h"
#include "hikari/core/error.h"
#include "hikari/integrators/device_scene.h"
#include "hikari/integrators/hit_aovs.h"
#include "hikari/integrators/path/path_kernel.h"

namespace hikari {

namespace {

/// Paths in flight at once: a wave is as many whole samples of every pixel as fit (at least
/// one). About 200 bytes each (state, hit, queues, shadow ray): 200 MiB, and enough threads to
/// fill a GPU several times over.
constexpr size_t k_wave_paths = size_t{1} << 20;

/// Whether the caller asked the render to stop.
bool cancelled(const RenderControl* control) {
    return control && control->cancel.load(std::memory_order_relaxed);
}

/// The arrays of a wave, allocated once for the largest and reused.
struct WaveArrays {
    PathState* paths;
    SurfaceHit* hits;
    uint32_t* queues[2];
    ShadowRay* shadows;
    uint32_t* counts;  ///< [0]: next ray queue, [1]: shadow queue
};

/// The scene's part of every wave's kernels, held in `arena`.
PathWave make_wave(const Scene& scene, const SceneIntersector& intersector,
                   const EmitterTable& emitters, const std::vector<Material>& materials,
                   const std::vector<float>& scale, const PixelFilter& filter,
                   const PathSettings& path, DeviceArena& arena) {
    PathWave w;
    w.scene = hold_intersector(intersector, arena);
    w.lights = arena.hold(std::span<const Light>(scene.lights));
    w.emitters = emitters.view();
    w.emitters.entries = arena.hold(emitters.entries());
    w.emitters.cdf = arena.hold(emitters.cdf());
    w.emitters.triangle_entry = arena.hold(emitters.triangle_entries());
    w.emitters.light_entry = arena.hold(emitters.light_entries());
    w.emitters.lights = w.lights.data;
    w.materials = arena.hold(std::span<const Material>(materials)).data;
    w.scale = arena.hold(std::span<const float>(scale)).data;
    w.sky = arena.hold_one(scene.sky);
    w.background = scene.background;
    if (const EnvironmentLight* environment = find_environment(scene.lights))
        w.environment = arena.hold_one(*environment);
    w.has_area_lights = has_area_light(scene.lights);
    w.frame = make_camera_frame(scene.camera);
    w.filter_inverse_cdf = arena.hold(filter.inverse_cdf()).data;
    w.filter_width = filter.width();
    w.max_depth = path.max_depth;
    w.clamp = path.clamp;
    return w;
}

}  // namespace

std::string path_kernel_refusal(const Scene& scene, const PathSettings& path) {
    if (const EnvironmentLight* environment = find_environment(scene.lights);
        environment && environment->map)
        return "environment maps are not in the kernels yet (constant environment lights, "
               "point, spot, directional and area lights and emissive triangles are)";
    if (std::string refusal = image_texture_refusal(scene); !refusal.empty()) return refusal;
    if (path.time_limit_seconds > 0.0f) return "--time-limit is not in the kernels yet";
    if (path.progressive_seconds > 0.0f) return "--progressive is not in the kernels yet";
    return {};
}

Framebuffer render_path_kernels(const Scene& scene, Film film, const RenderSettings& settings,
                                const PathSettings& path, ExecutionDevice device) {
    if (device == ExecutionDevice::cuda) require_cuda_device("--device cuda");
    if (const std::string refusal = path_kernel_refusal(scene, path); !refusal.empty())
        throw InputError(fmt::format(
            "{} path: {}", device == ExecutionDevice::cuda ? "--device cuda" : "kernels", refusal));
    const Camera& cam = scene.camera;
    Framebuffer fb(std::move(film), cam.width, cam.height, settings.aov_buffers);
    bool built = true;
    const std::shared_ptr<const SceneIntersector> intersector =
        scene_intersector(scene, settings.cache, &built);
    report_bvh_stats(*intersector, settings.stats, built);
    const EmitterTable emitters(scene);
    const std::vector<Material> materials = device_materials(scene);
    std::vector<float> scale;
    for (const Material& m : scene.materials) scale.push_back(energy_scale(m));
    const PixelFilter filter(path.filter, path.filter_width > 0.0f
                                              ? path.filter_width
                                              : default_filter_width(path.filter));

    DeviceArena arena(device);
    PathWave wave = make_wave(scene, *intersector, emitters, materials, scale, filter, path, arena);
    const size_t pixels = static_cast<size_t>(cam.width) * static_cast<size_t>(cam.height);
    const uint32_t target = static_cast<uint32_t>(std::max(1, path.samples_per_pixel));
    const uint32_t per_wave = static_cast<uint32_t>(
        std::clamp<size_t>(k_wave_paths / std::max<size_t>(pixels, 1), 1, target));
    const size_t capacity = pixels * per_wave;
    WaveArrays a{arena.output<PathState>(capacity),
                 arena.output<SurfaceHit>(capacity),
                 {arena.output<uint32_t>(capacity), arena.output<uint32_t>(capacity)},
                 arena.output<ShadowRay>(capacity),
                 arena.output<uint32_t>(2)};
    wave.paths = a.paths;
    wave.hits = a.hits;
    Vec3* sums = arena.output<Vec3>(pixels);
    uint32_t* bad = arena.output<uint32_t>(pixels);

    if (settings.aov_buffers) {
        SurfaceHit* centre = arena.output<SurfaceHit>(pixels);
        launch_path_kernel(device, pixels, PixelCentreHits{wave.scene, wave.frame, centre});
        for (size_t i = 0; i < pixels; ++i) {
            if (centre[i].kind == HitKind::none) continue;
            const int x = static_cast<int>(i % static_cast<size_t>(cam.width));
            const int y = static_cast<int>(i / static_cast<size_t>(cam.width));
            const Ray ray =
                camera_ray(wave.frame, static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
            store_hit_aovs(fb, i, ray.direction, centre[i]);
        }
    }

    RenderControl* control = settings.control;
    if (control) control->work_total = pixels * target;
    uint64_t rays = 0;
    uint32_t done = 0;
    while (done < target && !cancelled(control)) {
        wave.first_sample = done;
        wave.samples = std::min(per_wave, target - done);
        const size_t paths = pixels * wave.samples;
        /* 1. camera rays */
        int current = 0;
        launch_path_kernel(device, paths, GenerateCameraRays{wave, a.queues[current]});
        size_t queued = paths;
        while (queued > 0) {
            rays += queued;
            /* 2. nearest hits */
            launch_path_kernel(device, queued, IntersectRays{wave, a.queues[current]});
            /* 3. shading: light met, light samples, next rays */
            a.counts[0] = a.counts[1] = 0;
            launch_path_kernel(device, queued,
                               ShadePaths{wave, a.queues[current], a.queues[1 - current],
                                          &a.counts[0], a.shadows, &a.counts[1]});
            /* 4. shadow rays */
            rays += a.counts[1];
            launch_path_kernel(device, a.counts[1], TraceShadowRays{wave, a.shadows});
            queued = a.counts[0];
            current = 1 - current;
        }
        launch_path_kernel(device, pixels, ResolvePixels{wave, sums, bad});
        done += wave.samples;
        if (control) control->work_done.fetch_add(paths, std::memory_order_relaxed);
    }
    const uint32_t samples = std::max(done, 1u);
    const float inverse = 1.0f / static_cast<float>(samples);
    for (size_t i = 0; i < pixels; ++i) fb.set_color(i, sums[i] * inverse);
    if (settings.stats) {
        uint64_t bad_samples = 0;
        for (size_t i = 0; i < pixels; ++i) bad_samples += bad[i];
        settings.stats->rays_traced += rays;
        settings.stats->paths_traced += pixels * static_cast<uint64_t>(done);
        settings.stats->bad_samples += bad_samples;
    }
    return fb;
}

}  // namespace hikari
