#include "hikari/integrators/whitted/whitted_kernels.h"

#include <algorithm>
#include <optional>
#include <span>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "hikari/bvh/scene_intersector.h"
#include "hikari/core/error.h"
#include "hikari/frame/subpixel.h"
#include "hikari/integrators/device_scene.h"
#include "hikari/integrators/hit_aovs.h"
#include "hikari/integrators/whitted/whitted_kernel.h"
#include "hikari/shading/lights.h"

namespace hikari {

namespace {

/// `scene` with no primitive casting a shadow (`--shadows none`), as render_whitted takes it.
Scene without_shadow_casters(Scene scene) {
    for (Sphere& s : scene.spheres) s.casts_shadow = false;
    for (Plane& p : scene.planes) p.casts_shadow = false;
    scene.triangles.casts_shadow.assign(scene.triangles.size(), 0);
    return scene;
}

/// The kernel's views: of the scene and its BVHs on the CPU, of their copies on a GPU.
WhittedPixelKernel make_kernel(const Scene& scene, const SceneIntersector& intersector,
                               const WhittedScene& shading, const std::vector<Material>& materials,
                               std::span<const Vec2> samples, int max_depth, DeviceArena& arena) {
    WhittedPixelKernel k{.scene = hold_intersector(intersector, arena),
                         .shading = shading,
                         .frame = make_camera_frame(scene.camera),
                         .camera_cones = CameraCones(scene.camera)};
    k.textured = std::any_of(scene.materials.begin(), scene.materials.end(),
                             [](const Material& m) { return m.texture.has_value(); });
    k.shading.lighting.lights = arena.hold(std::span<const Light>(scene.lights)).data;
    k.shading.materials = arena.hold(std::span<const Material>(materials)).data;
    k.shading.sky = arena.hold_one(scene.sky);
    k.samples = arena.hold(samples);
    k.max_depth = max_depth;
    return k;
}

}  // namespace

std::string whitted_kernel_refusal(const Scene& scene, const WhittedSettings& whitted) {
    if (std::string refusal = delta_lights_refusal(scene); !refusal.empty()) return refusal;
    if (std::string refusal = image_texture_refusal(scene); !refusal.empty()) return refusal;
    if (whitted.analytic_area_shadows) return "--shadows analytic is not in the kernels yet";
    if (whitted.max_depth + 1 > k_whitted_kernel_stack)
        return fmt::format("--max-depth {} is past the kernels' {}", whitted.max_depth,
                           k_whitted_kernel_stack - 1);
    return {};
}

Framebuffer render_whitted_kernels(const Scene& scene, Film film, const RenderSettings& settings,
                                   const WhittedSettings& whitted, ExecutionDevice device) {
    if (!whitted.shadow_rays) {
        WhittedSettings with_rays = whitted;
        with_rays.shadow_rays = true;
        return render_whitted_kernels(without_shadow_casters(scene), std::move(film), settings,
                                      with_rays, device);
    }
    if (device == ExecutionDevice::cuda) require_cuda_device("--device cuda");
    if (const std::string refusal = whitted_kernel_refusal(scene, whitted); !refusal.empty())
        throw InputError(fmt::format("{} raytrace: {}",
                                     device == ExecutionDevice::cuda ? "--device cuda" : "kernels",
                                     refusal));
    const Camera& cam = scene.camera;
    Framebuffer fb(std::move(film), cam.width, cam.height, settings.aov_buffers);
    const std::shared_ptr<const SceneIntersector> intersector =
        scene_intersector(scene, settings.cache);
    // The sample points of render_whitted: the centre, or stratified jittered points.
    std::vector<Vec2> samples;
    if (whitted.samples_per_pixel == 1)
        samples.push_back({0.5f, 0.5f});
    else
        for (int s = 0; s < whitted.samples_per_pixel; ++s)
            samples.push_back(subpixel_sample(s, whitted.samples_per_pixel));

    DeviceArena arena(device);
    const WhittedScene shading(scene, whitted.light_samples);
    const std::vector<Material> materials = device_materials(scene);
    WhittedPixelKernel kernel =
        make_kernel(scene, *intersector, shading, materials, samples, whitted.max_depth, arena);
    const size_t pixels = static_cast<size_t>(cam.width) * static_cast<size_t>(cam.height);
    kernel.colours = arena.output<Vec3>(pixels);
    if (settings.aov_buffers) kernel.first_hits = arena.output<SurfaceHit>(pixels);
    launch_whitted_kernel(device, pixels, kernel);

    for (size_t i = 0; i < pixels; ++i) fb.set_color(i, kernel.colours[i]);
    if (settings.aov_buffers) {
        const CameraFrame& frame = kernel.frame;
        for (size_t i = 0; i < pixels; ++i) {
            if (kernel.first_hits[i].kind == HitKind::none) continue;
            const int x = static_cast<int>(i % static_cast<size_t>(cam.width));
            const int y = static_cast<int>(i / static_cast<size_t>(cam.width));
            const Ray centre =
                camera_ray(frame, static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
            store_hit_aovs(fb, i, centre.direction, kernel.first_hits[i]);
        }
    }
    if (settings.control) {
        settings.control->work_total = 1;
        settings.control->work_done = 1;
    }
    return fb;
}

}  // namespace hikari
