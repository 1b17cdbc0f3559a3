#include "hikari/integrators/path/path_tracer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

#include <fmt/format.h>

#include "hikari/bvh/scene_intersector.h"
#include "hikari/core/sobol.h"
#include "hikari/frame/tiles.h"
#include "hikari/geometry/ray_offset.h"
#include "hikari/integrators/hit_aovs.h"
#include "hikari/integrators/path/caustic_light_tracer.h"
#include "hikari/integrators/path/emitters.h"
#include "hikari/integrators/path/path_estimator.h"
#include "hikari/shading/bsdf/scattering.h"
#include "hikari/shading/lights.h"
#include "hikari/shading/material_eval.h"

namespace hikari {

namespace {

using Clock = std::chrono::steady_clock;

/// Everything a render's paths read.
class PathIntegrator {
  public:
    PathIntegrator(const Scene& scene, const PathSettings& settings, BuildCache* cache)
        : m_scene(scene),
          m_settings(settings),
          m_kept_intersector(scene_intersector(scene, cache, &m_built_intersector)),
          m_intersector(*m_kept_intersector),
          m_emitters(scene),
          m_environment(find_environment(scene.lights)),
          m_has_area_lights(has_area_light(scene.lights)),
          m_caustics_from_lights(settings.light_traced_caustics &&
                                 traces_caustics_from_lights(scene)) {
        m_scale.reserve(scene.materials.size());
        for (const Material& m : scene.materials) m_scale.push_back(energy_scale(m));
    }

    const SceneIntersector& intersector() const { return m_intersector; }
    /// Each material's energy_scale.
    const std::vector<float>& scale() const { return m_scale; }
    /// Whether the caustic paths are the light tracer's (integrators/path/caustic_light_tracer.h).
    bool caustics_from_lights() const { return m_caustics_from_lights; }
    /// Whether this render built the intersector (false: kept from an earlier render).
    bool built_intersector() const { return m_built_intersector; }

    /// The radiance arriving along `ray`, from one path; `rays` counts the rays it traces.
    Vec3 radiance(Ray ray, SobolSampler& sampler, uint64_t& rays) const {
        Vec3 sum(0.0f), throughput(1.0f);
        // Emitters found by a camera ray or after a delta bounce count fully (no light sample
        // could have found them); after a smooth bounce they are weighed against light sampling.
        bool specular = true, first_smooth = false;
        float bsdf_pdf = 0.0f;
        Vec3 last_normal(0.0f);
        for (int bounce = 0;; ++bounce) {
            SurfaceHit hit;
            ++rays;
            const bool found = m_intersector.closest(ray, {0.0f, k_infinity}, hit);
            if (m_has_area_lights) {
                const std::optional<LightFaceHit> face = nearest_light_face(
                    m_scene.lights, ray.origin, ray.direction, found ? hit.t : k_infinity);
                if (face) {
                    const float w =
                        specular ? 1.0f
                                 : power_heuristic(bsdf_pdf,
                                                   m_emitters.light_pdf(face->light, last_normal,
                                                                        ray.direction, face->t));
                    sum += throughput * face_radiance(m_scene.lights[face->light]) * w;
                    break;
                }
            }
            if (!found) {
                sum += throughput * escaped(ray.direction, specular, bsdf_pdf, last_normal);
                break;
            }
            const Material& material = m_scene.materials[hit.material];
            const bool front = dot(hit.geometric_normal, ray.direction) < 0.0f;
            // A caustic path (the eye's vertex smooth, the light's a mirror or glass bounce) off
            // an emissive triangle is the light tracer's, which finds it far more often.
            const bool light_traced = m_caustics_from_lights && bounce >= 2 && specular &&
                                      first_smooth && hit.kind == HitKind::triangle &&
                                      m_emitters.emits(hit.index);
            if (front && max_component(material.emission) > 0.0f && !light_traced) {
                const float light_pdf =
                    hit.kind == HitKind::triangle
                        ? m_emitters.triangle_pdf(hit.index, ray.direction, hit.t)
                        : 0.0f;
                sum += throughput * material.emission *
                       (specular ? 1.0f : power_heuristic(bsdf_pdf, light_pdf));
            }
            // The random numbers of this vertex, drawn whether used or not, so that every vertex
            // of every path reads the same dimensions.
            const float u_choice = sampler.next_1d();
            const Vec2 u_light = sampler.next_2d();
            const float u_lobe = sampler.next_1d();
            const Vec2 u_direction = sampler.next_2d();
            const float u_roulette = sampler.next_1d();

            const ScatterFrame at = scatter_frame_at(hit, ray.direction, front);
            const Scattering bsdf(material_at(hit, at), m_scale[hit.material]);
            if (bsdf.black()) break;
            if (bsdf.smooth() && !m_emitters.empty())
                sum += throughput * light_sample(hit.position, at, bsdf, u_choice, u_light, rays);
            if (bounce >= m_settings.max_depth) break;

            const ScatterSample next = bsdf.sample(at, u_lobe, u_direction);
            if (!(max_component(next.weight) > 0.0f)) break;
            throughput = throughput * next.weight;
            specular = next.delta;
            if (bounce == 0) first_smooth = !next.delta;
            bsdf_pdf = next.pdf;
            last_normal = at.normal;
            if (bounce + 1 >= k_roulette_after) {
                // Russian roulette: continue with probability q, carrying 1/q (unbiased).
                const float q = std::min(1.0f, max_component(throughput));
                if (!(u_roulette < q)) break;
                throughput = throughput / q;
            }
            const Vec3 side = dot(next.direction, at.geometric_normal) > 0.0f
                                  ? at.geometric_normal
                                  : -at.geometric_normal;
            ray = {offset_ray_origin(hit.position, side), next.direction};
        }
        return sum;
    }

  private:
    /// The material at `hit`, its texture applied.
    MaterialSample<float> material_at(const SurfaceHit& hit, const ScatterFrame& at) const {
        return material_at_hit(m_scene, m_intersector, hit, at);
    }

    /// What a ray that leaves the scene along `dir` brings back: the environment light (weighed
    /// against light sampling after a smooth bounce), else, for camera rays and mirror chains,
    /// the backdrop (the sky or background colour, which lights nothing).
    Vec3 escaped(Vec3 dir, bool specular, float bsdf_pdf, Vec3 last_normal) const {
        if (m_environment) {
            const float w =
                specular ? 1.0f
                         : power_heuristic(bsdf_pdf, m_emitters.environment_pdf(dir, last_normal));
            return m_environment->radiance_from(dir) * w;
        }
        return specular ? m_scene.sky.colour(dir, m_scene.background) : Vec3(0.0f);
    }

    /// Next-event estimation at `p`: one light sample, its shadow ray, weighed by MIS.
    Vec3 light_sample(Vec3 p, const ScatterFrame& at, const Scattering& bsdf, float u_choice,
                      Vec2 u, uint64_t& rays) const {
        const EmitterSample light = m_emitters.sample(p, at.normal, u_choice, u);
        if (!(light.pdf > 0.0f) || !(max_component(light.radiance) > 0.0f)) return Vec3(0.0f);
        float bsdf_pdf = 0.0f;
        const Vec3 f = bsdf.evaluate(at, light.to_light, bsdf_pdf);
        if (!(max_component(f) > 0.0f)) return Vec3(0.0f);
        // Stop just short of a sampled surface point, or the light's own face would block it.
        const float t_max =
            std::isinf(light.distance) ? k_infinity : light.distance * (1.0f - 1e-4f);
        ++rays;
        if (m_intersector.occluded({offset_ray_origin(p, at.geometric_normal), light.to_light},
                                   {0.0f, t_max}))
            return Vec3(0.0f);
        const float w = light.delta ? 1.0f : power_heuristic(light.pdf, bsdf_pdf);
        return f * light.radiance * (dot(at.normal, light.to_light) * w / light.pdf);
    }

    const Scene& m_scene;
    const PathSettings& m_settings;
    bool m_built_intersector = true;
    std::shared_ptr<const SceneIntersector> m_kept_intersector;
    const SceneIntersector& m_intersector;
    EmitterTable m_emitters;
    const EnvironmentLight* m_environment;
    bool m_has_area_lights;
    bool m_caustics_from_lights;
    std::vector<float> m_scale;  ///< energy_scale per material
};

/// Whether the caller asked the render to stop.
bool cancelled(const RenderControl* control) {
    return control && control->cancel.load(std::memory_order_relaxed);
}

/// A render's sample sums and how they are scheduled.
class PathRender {
  public:
    PathRender(const Scene& scene, const RenderSettings& settings, const PathSettings& path)
        : m_scene(scene),
          m_settings(settings),
          m_path(path),
          m_integrator(scene, path, settings.cache),
          m_frame(make_camera_frame(scene.camera)),
          m_filter(path.filter, path.filter_width > 0.0f ? path.filter_width
                                                         : default_filter_width(path.filter)),
          m_sums(static_cast<size_t>(scene.camera.width) * scene.camera.height, Vec3(0.0f)) {
        if (m_integrator.caustics_from_lights())
            m_light_tracer = std::make_unique<CausticLightTracer>(
                scene, m_integrator.intersector(), m_integrator.scale(), m_filter, path.max_depth);
    }

    const PathIntegrator& integrator() const { return m_integrator; }

    /// Samples [first, first + count) of every pixel, added to the sums, and as many light
    /// paths as camera paths for the caustics.
    void add_samples(int first, int count) {
        add_camera_samples(first, count);
        if (!m_light_tracer || cancelled(m_settings.control)) return;
        const uint64_t pixels = m_sums.size();
        uint64_t rays = 0;
        m_light_tracer->trace(pixels * static_cast<uint64_t>(first),
                              pixels * static_cast<uint64_t>(count), rays, share());
        if (m_settings.stats) m_settings.stats->rays_traced += rays;
    }

    /// Samples [first, first + count) of every pixel from the camera.
    void add_camera_samples(int first, int count) {
        const int width = m_scene.camera.width;
        RenderControl* control = m_settings.control;
        for_each_tile(
            width, m_scene.camera.height, control,
            [&](const Tile& tile) {
                uint64_t rays = 0, bad = 0;
                for (int y = tile.y0; y < tile.y1; ++y)
                    for (int x = tile.x0; x < tile.x1; ++x) {
                        const size_t pixel = static_cast<size_t>(y) * width + x;
                        Vec3 sum(0.0f);
                        for (int s = first; s < first + count; ++s) {
                            // A pass of many samples per pixel may outlast the tile's own
                            // poll: a cancelled render stops within a few samples.
                            if ((s & 15) == 15 && cancelled(control)) return;
                            const Vec3 value = sample(x, y, pixel, static_cast<uint32_t>(s), rays);
                            if (is_finite(value))
                                sum += value;
                            else
                                ++bad;
                        }
                        m_sums[pixel] += sum;
                    }
                const uint64_t pixels = static_cast<uint64_t>(tile.x1 - tile.x0) *
                                        static_cast<uint64_t>(tile.y1 - tile.y0);
                if (m_settings.stats) {
                    m_settings.stats->rays_traced += rays;
                    m_settings.stats->paths_traced += pixels * static_cast<uint64_t>(count);
                    m_settings.stats->bad_samples += bad;
                }
                if (control)
                    control->work_done.fetch_add(pixels * count, std::memory_order_relaxed);
            },
            false);
    }

    /// The processes sharing the image, or null (frame/tile_share.h).
    const TileShare* share() const {
        return m_settings.control ? m_settings.control->share : nullptr;
    }

    /// Makes the light paths' sums those of every process sharing the image: each traced its
    /// runs of them, and their splats land on any tile.
    void sum_light_paths_over_parts() {
        if (m_light_tracer && share()) m_light_tracer->sum_over_parts(*share());
    }

    /// The mean of `samples` samples per pixel as linear RGB.
    Image mean(int samples) const {
        Image image(m_scene.camera.width, m_scene.camera.height);
        const float inverse = 1.0f / static_cast<float>(samples);
        for (size_t i = 0; i < m_sums.size(); ++i) image.pixels[i] = m_sums[i] * inverse;
        if (m_light_tracer) {
            const double paths = static_cast<double>(samples) * static_cast<double>(m_sums.size());
            const float per_path = static_cast<float>(1.0 / paths);
            for (size_t i = 0; i < m_sums.size(); ++i)
                image.pixels[i] += m_light_tracer->sum(i) * per_path;
        }
        return image;
    }

    /// The AOVs of every pixel, from the ray through its centre.
    void store_aovs(Framebuffer& fb) const {
        const int width = m_scene.camera.width;
        for_each_tile(
            width, m_scene.camera.height, nullptr,
            [&](const Tile& tile) {
                for (int y = tile.y0; y < tile.y1; ++y)
                    for (int x = tile.x0; x < tile.x1; ++x) {
                        const Ray ray = camera_ray(m_frame, static_cast<float>(x) + 0.5f,
                                                   static_cast<float>(y) + 0.5f);
                        SurfaceHit hit;
                        if (m_integrator.intersector().closest(ray, {0.0f, k_infinity}, hit))
                            store_hit_aovs(fb, static_cast<size_t>(y) * width + x, ray.direction,
                                           hit);
                    }
            },
            false);
    }

  private:
    /// Sample `s` of pixel (x, y): a camera ray through the point the pixel filter draws.
    Vec3 sample(int x, int y, size_t pixel, uint32_t s, uint64_t& rays) const {
        SobolSampler sampler(pixel_seed(pixel), s);
        const Vec2 offset = m_filter.offset(sampler.next_2d());
        const Ray ray = camera_ray(m_frame, static_cast<float>(x) + 0.5f + offset.x,
                                   static_cast<float>(y) + 0.5f + offset.y);
        Vec3 value = m_integrator.radiance(ray, sampler, rays);
        if (m_path.clamp > 0.0f) {
            const float peak = max_component(value);
            if (peak > m_path.clamp) value = value * (m_path.clamp / peak);
        }
        return value;
    }

    const Scene& m_scene;
    const RenderSettings& m_settings;
    const PathSettings& m_path;
    PathIntegrator m_integrator;
    CameraFrame m_frame;
    PixelFilter m_filter;
    std::vector<Vec3> m_sums;
    std::unique_ptr<CausticLightTracer> m_light_tracer;  ///< null: no caustics to trace
};

}  // namespace

Framebuffer render_path(const Scene& scene, Film film, const RenderSettings& settings,
                        const PathSettings& path) {
    const Camera& cam = scene.camera;
    Framebuffer fb(std::move(film), cam.width, cam.height, settings.aov_buffers);
    PathRender render(scene, settings, path);
    report_bvh_stats(render.integrator().intersector(), settings.stats,
                     render.integrator().built_intersector());
    if (settings.aov_buffers) render.store_aovs(fb);

    const int target = std::max(1, path.samples_per_pixel);
    const bool timed = path.time_limit_seconds > 0.0f,
               progressive = path.progressive_seconds > 0.0f;
    // The pixels this process samples: all, or its tiles of a shared image.
    const uint64_t pixels = owned_pixels(cam.width, cam.height, settings.control);
    if (settings.control) settings.control->work_total = pixels * static_cast<uint64_t>(target);
    const auto start = Clock::now();
    double next_snapshot = path.progressive_seconds;
    int samples = 0;
    while (samples < target) {
        // Without a clock to watch, every sample in one pass (each tile keeps its pixels' paths
        // together); with one, passes that double until one would overrun the limit or the next
        // snapshot, judged by the time per sample so far.
        int count = target - samples;
        if (timed || progressive) {
            count = std::min(count, std::max(1, samples));
            const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
            if (samples > 0) {
                const double per_sample = elapsed / samples;
                double budget = std::numeric_limits<double>::infinity();
                if (timed) budget = path.time_limit_seconds - elapsed;
                if (progressive) budget = std::min(budget, next_snapshot - elapsed);
                count = std::clamp(static_cast<int>(budget / per_sample), 1, count);
            }
        }
        render.add_samples(samples, count);
        samples += count;
        const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        if (timed && elapsed >= path.time_limit_seconds) break;
        if (timed && settings.control)
            settings.control->work_total =
                pixels * static_cast<uint64_t>(std::min<double>(
                             target, samples * path.time_limit_seconds / std::max(elapsed, 1e-3)));
        if (progressive && path.snapshot && elapsed >= next_snapshot && samples < target) {
            path.snapshot(render.mean(samples), samples);
            next_snapshot = elapsed + path.progressive_seconds;
        }
    }
    render.sum_light_paths_over_parts();
    const Image image = render.mean(samples);
    fb.set_colors(0, image.pixels.data(), image.pixels.size());
    return fb;
}

std::vector<std::string> path_scene_warnings(const Scene& scene) {
    std::vector<std::string> warnings;
    for (const Material& m : scene.materials) {
        const float total = scattered_fraction(m.kd, m.ks, m.reflectivity, m.transparency);
        if (total > 1.0f + 1e-4f)
            warnings.push_back(fmt::format(
                "material '{}' would reflect more light than it receives (max(kd + ks) + "
                "reflectivity + transparency = {:.3g} > 1); path tracing scales it by {:.3g}",
                m.name, total, 1.0f / total));
    }
    return warnings;
}

}  // namespace hikari
