#include "hikari/methods/registry.h"

#include <algorithm>
#include <array>
#include <utility>

#include <fmt/format.h>

#include "hikari/explain/algorithm_aovs.h"
#include "hikari/explain/explain.h"
#include "hikari/frame/depth_cue.h"
#include "hikari/frame/subpixel.h"
#include "hikari/frame/tile_share.h"
#include "hikari/integrators/path/path_kernels.h"
#include "hikari/integrators/whitted/whitted.h"
#include "hikari/integrators/whitted/whitted_kernels.h"
#include "hikari/raster/depth_sort.h"
#include "hikari/raster/lines/hidden_line.h"
#include "hikari/raster/lines/wireframe.h"
#include "hikari/raster/scanline.h"
#include "hikari/raster/shadow_map.h"
#include "hikari/raster/zbuffer.h"
#include "hikari/raster/zbuffer_kernels.h"
#include "hikari/scene/rebase.h"

namespace hikari {

namespace {

/// The ray tracer with its settings and `--shadows` (shadow rays, its default, or none).
Framebuffer ray_trace(const Scene& scene, Film film, const RenderSettings& settings,
                      const MethodSettings& own) {
    WhittedSettings whitted = own.whitted;
    whitted.samples_per_pixel = own.samples_per_pixel.value_or(whitted.samples_per_pixel);
    whitted.max_depth = own.max_depth.value_or(whitted.max_depth);
    const ShadowMode mode = own.shadows.value_or(ShadowMode::ray);
    whitted.shadow_rays = mode != ShadowMode::none;
    whitted.analytic_area_shadows = mode == ShadowMode::analytic;
    whitted.light_samples = own.light_samples;
    if (own.device == ExecutionDevice::cuda)
        return render_whitted_kernels(scene, std::move(film), settings, whitted, own.device);
    return render_whitted(scene, std::move(film), settings, whitted);
}

/// `--device cuda` for a method whose GPU kernels are not written yet (docs/gpu.md): no device,
/// or no kernels, said in one line.
void refuse_gpu_method(const MethodSettings& own, std::string_view method) {
    if (own.device != ExecutionDevice::cuda) return;
    require_cuda_device("--device cuda");
    throw InputError(fmt::format(
        "--device cuda: method {} has no GPU kernels yet (raytrace, path and zbuffer have; "
        "docs/gpu.md)",
        method));
}

/// Anti-aliasing by supersampling (`--spp N` for the raster methods): N whole renders, each
/// sampling every pixel at one of the sub-pixel points the ray tracer takes (frame/subpixel.h),
/// their linear colours averaged; the AOVs come from one more render at the pixel centres, as
/// the ray tracer's do. Costs N (+1 with AOVs) times one render; the shadow maps, which do not
/// depend on the sample point, are drawn once (RasterSettings::shared_shadow_maps).
template <class RenderPass>
Framebuffer supersample(Film film, const RenderSettings& settings, int spp, RenderPass&& pass) {
    const int width = film.width(), height = film.height();
    Framebuffer out =
        settings.aov_buffers
            ? pass(Film(width, height, FilmFormat::linear), settings, Vec2{})
            : Framebuffer(Film(width, height, FilmFormat::linear), width, height, false);
    RenderSettings colour_only = settings;
    colour_only.aov_buffers = false;
    std::vector<Vec3> sum(static_cast<size_t>(width) * static_cast<size_t>(height), Vec3(0.0f));
    for (int s = 0; s < spp; ++s) {
        const Vec2 at = subpixel_sample(s, spp);
        const Framebuffer fb = pass(Film(width, height, FilmFormat::linear), colour_only,
                                    Vec2{at.x - 0.5f, at.y - 0.5f});
        const auto& pixels = fb.film.linear().pixels;
        for (size_t i = 0; i < sum.size(); ++i) sum[i] += pixels[i];
    }
    for (Vec3& c : sum) c = c / static_cast<float>(spp);
    out.film = std::move(film);
    out.set_colors(0, sum.data(), sum.size());
    return out;
}

/// The path tracer with its settings. With a time limit and no --spp, samples go on until
/// the time is up.
Framebuffer path_trace(const Scene& scene, Film film, const RenderSettings& settings,
                       const MethodSettings& own) {
    PathSettings path = own.path;
    const bool timed = path.time_limit_seconds > 0.0f;
    path.samples_per_pixel =
        own.samples_per_pixel.value_or(timed ? k_max_samples_per_pixel : path.samples_per_pixel);
    path.max_depth = own.max_depth.value_or(path.max_depth);
    if (own.device == ExecutionDevice::cuda)
        return render_path_kernels(scene, std::move(film), settings, path, own.device);
    return render_path(scene, std::move(film), settings, path);
}

/// A raster method `render(scene, film, settings, raster)` with the raster settings and
/// `--shadows` (shadow maps, their default, volumes or none).
template <auto render>
Framebuffer rasterize(const Scene& scene, Film film, const RenderSettings& settings,
                      const MethodSettings& own) {
    RasterSettings raster = own.raster;
    raster.shadows = own.shadows.value_or(ShadowMode::map);
    raster.light_samples = own.light_samples;
    const int spp = own.samples_per_pixel.value_or(1);
    if (spp == 1) return render(scene, std::move(film), settings, raster);
    raster.shared_shadow_maps = std::make_shared<SharedShadowMaps>();
    return supersample(film, settings, spp, [&](Film pass, const RenderSettings& s, Vec2 offset) {
        raster.sample_offset = offset;
        return render(scene, std::move(pass), s, raster);
    });
}

/// The Z-buffer's kernels on the GPU (raster/zbuffer_kernels.h).
Framebuffer render_zbuffer_on_gpu(const Scene& scene, Film film, const RenderSettings& settings,
                                  const RasterSettings& raster) {
    return render_zbuffer_kernels(scene, std::move(film), settings, raster, ExecutionDevice::cuda);
}

/// The Z-buffer, on the CPU or, with `--device cuda`, as the GPU's tile-binned kernels.
Framebuffer zbuffer(const Scene& scene, Film film, const RenderSettings& settings,
                    const MethodSettings& own) {
    if (own.device == ExecutionDevice::cuda)
        return rasterize<&render_zbuffer_on_gpu>(scene, std::move(film), settings, own);
    return rasterize<&render_zbuffer>(scene, std::move(film), settings, own);
}

constexpr ShadowMode k_ray_shadow_modes[] = {ShadowMode::ray, ShadowMode::analytic,
                                             ShadowMode::none};
constexpr ShadowMode k_raster_shadow_modes[] = {ShadowMode::map,      ShadowMode::volume,
                                                ShadowMode::pcf,      ShadowMode::pcss,
                                                ShadowMode::analytic, ShadowMode::none};

constexpr MethodOption k_shadows_option = {
    "--shadows",
    "Shadows (Fig 4.24): ray (shadow rays; raytrace's default), map (shadow mapping; the "
    "raster methods' default), volume (shadow volumes, z-fail stencil), pcf (filtered maps, "
    "5x5 texels), pcss (percentage-closer soft shadows), analytic (area lights' visible part in "
    "closed form), none",
    ChoiceOption<std::optional<ShadowMode>>{
        k_shadow_choices,
        [](MethodSettings& s) -> std::optional<ShadowMode>& { return s.shadows; }}};

constexpr MethodOption k_light_samples_option = {
    "--light-samples",
    "Stratified samples per area or environment light per shaded point (default 16)",
    IntegerOption{1, 65536, [](MethodSettings& s) -> int& { return s.light_samples; }}};

constexpr MethodOption k_spp_option = {
    "--spp",
    "Samples per pixel (raytrace: 1 = pixel centres, more: stratified, default 1; raster "
    "methods: supersampling at the same sub-pixel points, one render per sample, default 1; "
    "path: default 64, or as many as --time-limit allows)",
    OptionalIntegerOption{1, k_max_samples_per_pixel, [](MethodSettings& s) -> std::optional<int>& {
                              return s.samples_per_pixel;
                          }}};

constexpr MethodOption k_max_depth_option = {
    "--max-depth",
    "raytrace: ray segments per path, the primary ray included (default 5); path: bounces "
    "after the first hit, 0 = direct light only (default 8)",
    OptionalIntegerOption{0, 64,
                          [](MethodSettings& s) -> std::optional<int>& { return s.max_depth; }}};

constexpr MethodOption k_device_option = {
    "--device",
    "Where the render runs: cpu (default) or cuda (an NVIDIA GPU; raytrace's kernels, "
    "docs/gpu.md)",
    ChoiceOption<ExecutionDevice>{k_device_choices,
                                  [](MethodSettings& s) -> ExecutionDevice& { return s.device; }}};

constexpr MethodOption k_ray_tracing_options[] = {
    k_spp_option, k_max_depth_option, k_shadows_option, k_light_samples_option, k_device_option,
};

constexpr MethodOption k_path_options[] = {
    k_spp_option,
    k_max_depth_option,
    k_device_option,
    {"--clamp",
     "Scale each sample's radiance down to at most this per channel (removes fireflies, "
     "biased; default 0 = off)",
     RealOption{0.0f, 1e30f, [](MethodSettings& s) -> float& { return s.path.clamp; }}},
    {"--caustics",
     "Caustics (light through mirror or glass onto a diffuse surface) from emissive triangles: "
     "light (traced from the lights and joined to the eye: no fireflies; default) or path (left "
     "to the camera paths, as plain path tracing does: the same mean, far noisier)",
     ChoiceOption<bool>{k_caustic_choices,
                        [](MethodSettings& s) -> bool& { return s.path.light_traced_caustics; }}},
    {"--time-limit",
     "Stop after this many seconds of path tracing (at least one sample per pixel); without "
     "--spp, sample until then",
     RealOption{0.0f, 1e7f, [](MethodSettings& s) -> float& { return s.path.time_limit_seconds; }}},
    {"--progressive",
     "Rewrite the output file about every this many seconds with the samples so far "
     "(atomically: a viewer always sees a whole image)",
     RealOption{0.0f, 1e7f,
                [](MethodSettings& s) -> float& { return s.path.progressive_seconds; }}},
    {"--filter",
     "Pixel filter: box (the pixel's square), gaussian, blackman-harris (samples drawn with "
     "the filter's density)",
     ChoiceOption<PixelFilterKind>{
         k_filter_choices, [](MethodSettings& s) -> PixelFilterKind& { return s.path.filter; }}},
    {"--filter-width",
     "Pixel filter width in pixels (default: 1 for box, 1.5 for gaussian and blackman-harris)",
     RealOption{0.0f, 16.0f, [](MethodSettings& s) -> float& { return s.path.filter_width; }}},
};

constexpr MethodOption k_cull_option = {
    "--cull",
    "Back-face culling (Fig 4.3): back drops triangles whose front (counter-clockwise) side "
    "faces away from the eye; none keeps all",
    ChoiceOption<bool>{k_cull_choices,
                       [](MethodSettings& s) -> bool& { return s.raster.cull_back_faces; }}};

constexpr MethodOption k_raster_options[] = {
    k_spp_option,
    {"--interp",
     "Raster shading interpolation: flat (one colour per polygon), gouraud (vertex colours "
     "blended), phong (normals interpolated, shaded per pixel)",
     ChoiceOption<Interpolation>{
         k_interpolation_choices,
         [](MethodSettings& s) -> Interpolation& { return s.raster.interp; }}},
    k_cull_option,
    k_shadows_option,
    {"--shadow-map-size", "Texels per side of each shadow map (a cube map has six faces)",
     IntegerOption{16, 16384, [](MethodSettings& s) -> int& { return s.raster.shadow_map_size; }}},
    k_light_samples_option,
};

/// The raster options and --device (the Z-buffer's).
constexpr MethodOption k_zbuffer_options[] = {
    k_raster_options[0], k_raster_options[1], k_raster_options[2], k_raster_options[3],
    k_raster_options[4], k_raster_options[5], k_device_option,
};

/// The raster options, and the depth sort's own step through its painting.
static_assert(std::size(k_raster_options) == 6, "the depth sort takes every raster option");
constexpr MethodOption k_depth_sort_options[] = {
    k_raster_options[0],
    k_raster_options[1],
    k_raster_options[2],
    k_raster_options[3],
    k_raster_options[4],
    k_raster_options[5],
    {"--paint-steps",
     "Paint only the first N polygons of the painting order (a piece of a split polygon counts "
     "as one), to watch Fig 4.6's painter part-way; 0 (the default) paints them all",
     IntegerOption{0, 1 << 30, [](MethodSettings& s) -> int& { return s.raster.paint_steps; }}},
};

constexpr MethodOption k_line_options[] = {
    {"--line-width", "Line width in pixels (wireframe, hidden lines)",
     RealOption{0.01f, 1000.0f, [](MethodSettings& s) -> float& { return s.lines.width; }}},
    {"--line-color", "Colour of every line, linear R,G,B (default: each face's material kd)",
     ColorOption{[](MethodSettings& s) -> std::optional<Vec3>& { return s.lines.color; }}},
    k_cull_option,
};

/// The line settings with --cull, which the line methods share with the raster methods.
LineSettings line_settings(const MethodSettings& own) {
    LineSettings lines = own.lines;
    lines.cull_back_faces = own.raster.cull_back_faces;
    return lines;
}

/// A line method's render function `render(scene, film, settings, lines)` as a RenderFunction.
template <auto render>
Framebuffer with_line_settings(const Scene& scene, Film film, const RenderSettings& settings,
                               const MethodSettings& own) {
    return render(scene, std::move(film), settings, line_settings(own));
}

/// A line method's `draw(scene, lines)` as a DrawFunction.
template <auto draw>
LineDrawing drawing_with_line_settings(const Scene& scene, const MethodSettings& own) {
    return draw(scene, line_settings(own));
}

/// Whether each material of `scene` is on some primitive (an unused one changes no image).
std::vector<bool> used_materials(const Scene& scene) {
    std::vector<bool> used(scene.materials.size(), false);
    for (const Sphere& s : scene.spheres) used[s.material] = true;
    for (const Plane& p : scene.planes) used[p.material] = true;
    for (const uint32_t m : scene.triangles.material) used[m] = true;
    return used;
}

/// "material 'glass'" or "materials 'glass', 'mirror'": the used materials for which `has`
/// holds; empty for none.
template <class Predicate>
std::string materials_where(const Scene& scene, Predicate&& has) {
    const std::vector<bool> used = used_materials(scene);
    std::string names;
    int count = 0;
    for (size_t m = 0; m < scene.materials.size(); ++m)
        if (used[m] && has(scene.materials[m]))
            names += fmt::format("{}'{}'", count++ == 0 ? "" : ", ", scene.materials[m].name);
    if (count == 0) return "";
    return (count == 1 ? "material " : "materials ") + names;
}

/// What the Whitted ray tracer leaves out of a scene: emission (light transport only).
std::vector<std::string> whitted_scene_warnings(const Scene& scene) {
    std::vector<std::string> warnings;
    const std::string emitting =
        materials_where(scene, [](const Material& m) { return m.emission != Vec3(0.0f); });
    if (!emitting.empty())
        warnings.push_back(fmt::format(
            "{}: emission is light only --method path sees; raytrace shades by the other "
            "coefficients",
            emitting));
    return warnings;
}

/// What the raster methods leave out: mirror reflection and refraction (secondary rays), and
/// emission.
std::vector<std::string> raster_scene_warnings(const Scene& scene) {
    std::vector<std::string> warnings = whitted_scene_warnings(scene);
    if (!warnings.empty())
        warnings.back().replace(warnings.back().find("raytrace"), 8, "this method");
    const std::string secondary = materials_where(
        scene, [](const Material& m) { return m.reflectivity > 0.0f || m.transparency > 0.0f; });
    if (!secondary.empty())
        warnings.push_back(fmt::format(
            "{}: reflectivity and transparency need secondary rays; a raster method draws each "
            "pixel's own surface only, without mirror images or what lies behind glass (raytrace "
            "and path trace them)",
            secondary));
    return warnings;
}

/// raytrace's values: its paths start with the camera ray, so --max-depth 0 leaves nothing.
std::string ray_trace_refusals(const MethodSettings& own) {
    if (own.max_depth == 0)
        return "--max-depth 0: raytrace needs at least 1 ray segment (the camera ray)";
    return "";
}

/// `explain -m zbuffer --pixel X,Y`: Alg 4.2's fragments at the pixel.
std::string explain_zbuffer(const Scene& scene, const MethodSettings& own, int x, int y) {
    return explain_zbuffer_pixel(scene, own.raster, x, y);
}

/// `explain -m raytrace --pixel X,Y`: the ray tree of the pixel's centre ray (Alg 4.3).
std::string explain_raytrace(const Scene& scene, const MethodSettings& own, int x, int y) {
    WhittedSettings whitted = own.whitted;
    if (own.max_depth) whitted.max_depth = *own.max_depth;
    return explain_raytrace_pixel(scene, whitted, x, y);
}

/// `explain -m scanline --row Y`: Alg 4.1's edge table, active edges and spans on the row.
std::string explain_scanline(const Scene& scene, const MethodSettings& own, int row) {
    return explain_scanline_row(scene, own.raster, row);
}

/// `explain -m depthsort`: the whole sort, its tests, reorderings and splits (Fig 4.6-4.9).
std::string explain_depth_sort_run(const Scene& scene, const MethodSettings& own) {
    return explain_depth_sort(scene, own.raster);
}

constexpr Aov k_zbuffer_aovs[] = {Aov::overdraw, Aov::culled};
constexpr Aov k_scanline_aovs[] = {Aov::spans, Aov::culled};
constexpr Aov k_depth_sort_aovs[] = {Aov::overdraw, Aov::paint_order, Aov::culled};

constexpr auto k_whitted = &ray_trace;
template <auto render>
constexpr auto k_raster = &rasterize<render>;

/// A hidden-surface method of the raster pipeline: the raster options, shadow modes and scene
/// warnings, colour as the sum of shading terms, and what it shows of its own work.
constexpr Method raster_method(std::string_view name, std::string_view summary,
                               RenderFunction render, AlgorithmAovs algorithm_aovs,
                               ExplainViews explain, StatsWords stats,
                               std::span<const MethodOption> options = k_raster_options) {
    return Method{.name = name,
                  .summary = summary,
                  .render = render,
                  .options = options,
                  .shadow_modes = k_raster_shadow_modes,
                  .warnings = &raster_scene_warnings,
                  .shading_terms = true,
                  .algorithm_aovs = algorithm_aovs,
                  .explain = explain,
                  .stats = stats};
}

constexpr std::array k_methods = {
    Method{.name = "raytrace",
           .summary =
               "Whitted ray tracing (Alg 4.3): nearest hit, shadow rays, reflection, refraction",
           .render = k_whitted,
           .options = k_ray_tracing_options,
           .shadow_modes = k_ray_shadow_modes,
           .warnings = &whitted_scene_warnings,
           .shading_terms = true,
           .explain = {.pixel = &explain_raytrace},
           .refuse_values = &ray_trace_refusals,
           .shares_tiles = true},
    Method{.name = "path",
           .summary = "path tracing (Kajiya 1986): global illumination, light sampling and BSDF "
                      "sampling combined by MIS",
           .render = &path_trace,
           .options = k_path_options,
           .warnings = &path_scene_warnings,
           .shares_tiles = true},
    raster_method("zbuffer",
                  "Z-buffer (Alg 4.2): rasterize every triangle, keep the nearest per pixel",
                  &zbuffer, {k_zbuffer_aovs, &zbuffer_algorithm_aov}, {.pixel = &explain_zbuffer},
                  {.work = "fragments depth-tested"}, k_zbuffer_options),
    raster_method("scanline",
                  "scanline (Alg 4.1): edge table, active edges, nearest segment per sample span",
                  k_raster<&render_scanline>, {k_scanline_aovs, &scanline_algorithm_aov},
                  {.row = &explain_scanline}, {.work = "sample spans"}),
    raster_method("depthsort",
                  "depth sort (Newell et al. 1972): sort, overlap tests, reorder, split cycles",
                  k_raster<&render_depth_sort>, {k_depth_sort_aovs, &depth_sort_algorithm_aov},
                  {.whole = &explain_depth_sort_run}, {.work = "pixel paints", .splits = true},
                  k_depth_sort_options),
    raster_method("depthsort-naive",
                  "painter's algorithm by centroid depth (Fig 4.7): fails on overlap cycles",
                  k_raster<&render_depth_sort_naive>, {}, {}, {.work = "pixel paints (naive)"}),
    Method{.name = "wireframe",
           .summary = "wireframe (Fig 4.1a): every edge of every face, anti-aliased lines",
           .render = &with_line_settings<&render_wireframe>,
           .options = k_line_options,
           .draw = &drawing_with_line_settings<&draw_wireframe>},
    Method{.name = "hiddenline",
           .summary = "hidden-line removal (Fig 4.1c, Appel 1967): visible parts of edges, exact "
                      "in object space",
           .render = &with_line_settings<&render_hidden_lines>,
           .options = k_line_options,
           .draw = &drawing_with_line_settings<&draw_hidden_lines>},
};

/// The names of the methods for which `has` holds, e.g. "zbuffer, depthsort".
template <class Predicate>
std::string names_where(Predicate&& has) {
    std::string list;
    for (const Method& m : k_methods)
        if (has(m)) list += fmt::format("{}{}", list.empty() ? "" : ", ", m.name);
    return list;
}

}  // namespace

std::span<const Method> methods() { return k_methods; }

const Method* find_method(std::string_view name) {
    for (const Method& m : k_methods)
        if (m.name == name) return &m;
    return nullptr;
}

Framebuffer render_scene(const Method& method, const Scene& scene, Film film,
                         RenderSettings settings, const MethodSettings& own) {
    if (worth_rebasing(scene.camera))
        return render_scene(method, rebased_to_camera(scene), std::move(film), settings, own);
    const TileShare* share = settings.control ? settings.control->share : nullptr;
    if (!scene.depth_cue) {
        Framebuffer fb = method.render(scene, std::move(film), settings, own);
        if (share) share->combine(fb);
        return fb;
    }
    settings.aov_buffers = true;
    Framebuffer fb =
        method.render(scene, Film(film.width(), film.height(), FilmFormat::linear), settings, own);
    if (share) share->combine(fb);  // the whole image before the blur reads across tiles
    if (!settings.control || !settings.control->cancel.load())
        apply_depth_cue(*scene.depth_cue, scene.background, fb);
    return fb;
}

LineDrawing draw_scene(const Method& method, const Scene& scene, const MethodSettings& own) {
    if (worth_rebasing(scene.camera)) return draw_scene(method, rebased_to_camera(scene), own);
    LineDrawing drawing = method.draw(scene, own);
    if (scene.depth_cue) return depth_cued(drawing, *scene.depth_cue);
    return drawing;
}

std::string shading_term_methods() {
    return names_where([](const Method& m) { return m.shading_terms; });
}

std::string drawing_methods() {
    return names_where([](const Method& m) { return m.draw != nullptr; });
}

bool has_algorithm_aov(const Method& method, Aov aov) {
    const std::span<const Aov> aovs = method.algorithm_aovs.aovs;
    return std::find(aovs.begin(), aovs.end(), aov) != aovs.end();
}

std::string methods_with_algorithm_aov(Aov aov) {
    return names_where([aov](const Method& m) { return has_algorithm_aov(m, aov); });
}

bool has_explain_view(const Method& method) {
    return method.explain.pixel || method.explain.row || method.explain.whole;
}

bool does_shadows(const Method& method, ShadowMode mode) {
    return std::find(method.shadow_modes.begin(), method.shadow_modes.end(), mode) !=
           method.shadow_modes.end();
}

std::string shadow_mode_list(const Method& method) {
    std::string list;
    for (const ShadowMode mode : method.shadow_modes)
        list += fmt::format("{}{}", list.empty() ? "" : ", ",
                            choice_name<std::optional<ShadowMode>>(k_shadow_choices, mode));
    return list;
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
