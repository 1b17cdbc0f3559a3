#include "hikari/methods/registry.h"

#include <algorithm>
#include <array>
#include <utility>

#include "hikari/frame/depth_cue.h"
#include "hikari/integrators/whitted/whitted.h"
#include "hikari/raster/depth_sort.h"
#include "hikari/raster/scanline.h"
#include "hikari/raster/zbuffer.h"

namespace hikari {

namespace {

/// A method function `render(scene, film, settings, own)` as a RenderFunction: `part` picks its
/// own settings out of MethodSettings.
template <auto render, auto part>
Framebuffer with_own_settings(const Scene& scene, Film film, const RenderSettings& settings,
                              const MethodSettings& own) {
    return render(scene, std::move(film), settings, own.*part);
}

constexpr MethodOption k_ray_tracing_options[] = {
    {"--spp", "Samples per pixel (1 = pixel centres; more: stratified)",
     IntegerOption{1, 65536,
                   [](MethodSettings& s) -> int& { return s.whitted.samples_per_pixel; }}},
    {"--max-depth", "Ray segments per path, the primary ray included (Whitted recursion)",
     IntegerOption{1, 64, [](MethodSettings& s) -> int& { return s.whitted.max_depth; }}},
};

constexpr MethodOption k_raster_options[] = {
    {"--interp",
     "Raster shading interpolation: flat (one colour per polygon), gouraud (vertex colours "
     "blended), phong (normals interpolated, shaded per pixel)",
     ChoiceOption<Interpolation>{
         k_interpolation_choices,
         [](MethodSettings& s) -> Interpolation& { return s.raster.interp; }}},
    {"--cull",
     "Raster back-face culling (Fig 4.3): back drops triangles whose front (counter-clockwise) "
     "side faces away from the eye; none keeps all",
     ChoiceOption<bool>{k_cull_choices,
                        [](MethodSettings& s) -> bool& { return s.raster.cull_back_faces; }}},
};

constexpr auto k_whitted = &with_own_settings<&render_whitted, &MethodSettings::whitted>;
template <auto render>
constexpr auto k_raster = &with_own_settings<render, &MethodSettings::raster>;

constexpr std::array k_methods = {
    Method{"raytrace",
           "Whitted ray tracing (Alg 4.3): nearest hit, shadow rays, reflection, refraction",
           k_whitted, k_ray_tracing_options},
    Method{"zbuffer", "Z-buffer (Alg 4.2): rasterize every triangle, keep the nearest per pixel",
           k_raster<&render_zbuffer>, k_raster_options},
    Method{"scanline",
           "scanline (Alg 4.1): edge table, active edges, nearest segment per sample span",
           k_raster<&render_scanline>, k_raster_options},
    Method{"depthsort",
           "depth sort (Newell et al. 1972): sort, overlap tests, reorder, split cycles",
           k_raster<&render_depth_sort>, k_raster_options},
    Method{"depthsort-naive",
           "painter's algorithm by centroid depth (Fig 4.7): fails on overlap cycles",
           k_raster<&render_depth_sort_naive>, k_raster_options},
};

}  // namespace

std::span<const Method> methods() { return k_methods; }

const Method* find_method(std::string_view name) {
    for (const Method& m : k_methods)
        if (m.name == name) return &m;
    return nullptr;
}

Framebuffer render_scene(const Method& method, const Scene& scene, Film film,
                         RenderSettings settings, const MethodSettings& own) {
    if (!scene.depth_cue) return method.render(scene, std::move(film), settings, own);
    settings.aov_buffers = true;
    Framebuffer fb =
        method.render(scene, Film(film.width(), film.height(), FilmFormat::linear), settings, own);
    if (!settings.control || !settings.control->cancel.load())
        apply_depth_cue(*scene.depth_cue, scene.background, fb);
    return fb;
}

std::vector<const MethodOption*> method_options() {
    std::vector<const MethodOption*> all;
    for (const Method& m : k_methods)
        for (const MethodOption& option : m.options)
            if (std::none_of(all.begin(), all.end(),
                             [&](const MethodOption* seen) { return seen->flag == option.flag; }))
                all.push_back(&option);
    return all;
}

bool takes_option(const Method& method, std::string_view flag) {
    return std::any_of(method.options.begin(), method.options.end(),
                       [&](const MethodOption& option) { return option.flag == flag; });
}

}  // namespace hikari
