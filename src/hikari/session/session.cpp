#include "hikari/session/session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <stop_token>
#include <thread>
#include <utility>

#include <fmt/format.h>
#include <tbb/global_control.h>

#include "hikari/core/cancel.h"
#include "hikari/core/error.h"
#include "hikari/core/memory_budget.h"
#include "hikari/explain/algorithm_aovs.h"
#include "hikari/io/models/model_file.h"
#include "hikari/io/models/model_scene.h"
#include "hikari/io/scene/scene_json.h"
#include "hikari/raster/lines/wireframe.h"
#include "hikari/shading/shading_terms.h"

namespace hikari {

namespace {

using Clock = std::chrono::steady_clock;

/// `--wireframe-overlay`'s line colour: near black, a figure's ink.
constexpr Vec3 k_overlay_colour{0.02f, 0.02f, 0.02f};

}  // namespace

Scene load_scene_source(const SceneSource& source, std::vector<std::string>& warnings) {
    SceneLoadOptions load(source.overrides);
    load.crease_angle = source.crease_angle;
    const bool model = !source.json_text && is_model_file(source.file);
    if (source.ground && !model)
        warnings.emplace_back("--ground adds a plane under a model file; the scene has its own");
    if (source.json_text)
        return parse_scene(*source.json_text, source.file.empty() ? "scene" : source.file,
                           source.base_dir, warnings, load);
    if (source.file.empty()) return load_default_scene(load);
    if (model)
        return load_model_scene(source.file, {.ground = source.ground, .mesh = {}}, warnings, load);
    return load_scene_file(source.file, warnings, load);
}

namespace {

/// Whether two scenes hold the same geometry, value for value: what a BVH is built from.
bool same_geometry(const Scene& a, const Scene& b) {
    const auto same_spheres = [](const Sphere& x, const Sphere& y) {
        return x.center == y.center && x.radius == y.radius && x.material == y.material &&
               x.id == y.id && x.casts_shadow == y.casts_shadow && x.segments == y.segments;
    };
    const auto same_planes = [](const Plane& x, const Plane& y) {
        return x.point == y.point && x.normal == y.normal && x.material == y.material &&
               x.id == y.id && x.casts_shadow == y.casts_shadow && x.uv_scale == y.uv_scale;
    };
    const TriangleSet &s = a.triangles, &t = b.triangles;
    return std::equal(a.spheres.begin(), a.spheres.end(), b.spheres.begin(), b.spheres.end(),
                      same_spheres) &&
           std::equal(a.planes.begin(), a.planes.end(), b.planes.begin(), b.planes.end(),
                      same_planes) &&
           s.positions == t.positions && s.normals == t.normals &&
           std::equal(s.uvs.begin(), s.uvs.end(), t.uvs.begin(), t.uvs.end(),
                      [](Vec2 x, Vec2 y) { return x.x == y.x && x.y == y.y; }) &&
           s.colors == t.colors && s.indices == t.indices && s.material == t.material &&
           s.id == t.id && s.casts_shadow == t.casts_shadow && s.edge_flags == t.edge_flags &&
           a.primitive_count == b.primitive_count;
}

/// Refuses a buffer `method` has no picture of (the command line refuses it before any work;
/// other front ends meet it here).
void check_aov(const Method& method, Aov aov) {
    if (is_algorithm_aov(aov) && !has_algorithm_aov(method, aov))
        throw InputError(fmt::format("this AOV shows the work of {}, not of method {}",
                                     methods_with_algorithm_aov(aov), method.name));
    if (shading_term_of(aov) && !method.shading_terms)
        throw InputError(fmt::format(
            "method {} does not shade by ambient + diffuse + specular (Fig 4.29), so it has no "
            "such term (methods that do: {})",
            method.name, shading_term_methods()));
}

/// RenderRequest::threads, for as long as it lives (0: every core).
class ThreadLimit {
  public:
    explicit ThreadLimit(int threads) {
        if (threads > 0)
            m_limit.emplace(tbb::global_control::max_allowed_parallelism,
                            static_cast<size_t>(threads));
    }

  private:
    std::optional<tbb::global_control> m_limit;
};

/// Watches a running render for its caller: reports progress about ten times a second and
/// passes a cancellation on to the method. No thread when there is nothing to watch.
class RenderWatch {
  public:
    RenderWatch(const RenderRequest& request, RenderControl& control) {
        if (!request.progress && !request.cancel) return;
        m_thread = std::jthread([&request, &control, this](const std::stop_token& stop) {
            const auto start = Clock::now();
            auto reported = start;
            std::unique_lock lock(m_mutex);
            while (
                !m_wake.wait_for(lock, stop, std::chrono::milliseconds(10), [] { return false; })) {
                if (stop.stop_requested()) break;
                if ((request.cancel && request.cancel->cancelled()) || cancel_requested())
                    control.cancel.store(true);
                const auto now = Clock::now();
                if (!request.progress || now - reported < std::chrono::milliseconds(100)) continue;
                reported = now;
                const uint64_t total = control.work_total.load();
                request.progress({total ? double(control.work_done.load()) / double(total) : 0.0,
                                  std::chrono::duration<double>(now - start).count()});
            }
        });
    }

  private:
    std::mutex m_mutex;
    std::condition_variable_any m_wake;
    std::jthread m_thread;  ///< last: joined first, while the members above live
};

/// The scene `source` names, loaded inside a MemoryScope (the loaders' buffers count together);
/// `grown` gets what the process grew by, which the scene holds from then on.
Scene load_measured(const SceneSource& source, std::vector<std::string>& warnings, double& grown) {
    const MemoryScope scope;
    const double before = process_memory_bytes();
    Scene scene = load_scene_source(source, warnings);
    grown = std::max(0.0, process_memory_bytes() - before);
    return scene;
}

}  // namespace

const Method& method_named(std::string_view name) {
    if (const Method* method = find_method(name)) return *method;
    std::string names;
    for (const Method& m : methods())
        names += fmt::format("{}{}", names.empty() ? "" : ", ", m.name);
    throw InputError(fmt::format("unknown method '{}' (methods: {})", name, names));
}

void check_image_memory(const Camera& camera) {
    const double pixels = static_cast<double>(camera.width) * camera.height;
    // colour + depth + id + normal in the framebuffer, one more image for the output.
    check_memory_need(pixels * (sizeof(Vec3) * 3 + sizeof(float) + sizeof(uint32_t)),
                      fmt::format("a {}x{} image", camera.width, camera.height));
}

Camera resized_camera(Camera camera, int width, int height) {
    if (width > 0 && height == 0)
        height = std::max(1, static_cast<int>(std::lround(static_cast<double>(width) *
                                                          camera.height / camera.width)));
    if (height > 0 && width == 0)
        width = std::max(1, static_cast<int>(std::lround(static_cast<double>(height) *
                                                         camera.width / camera.height)));
    if (width > 0) camera.width = width;
    if (height > 0) camera.height = height;
    return camera;
}

Session::Session(SceneSource source)
    : m_source(std::move(source)), m_cache(std::make_unique<BuildCache>()) {
    const auto start = Clock::now();
    double grown = 0;
    Scene scene = load_measured(m_source, m_warnings, grown);
    m_load_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    adopt(std::move(scene));
    m_scene_memory.emplace(grown);
}

Session::Session(Scene scene) : m_cache(std::make_unique<BuildCache>()) { adopt(std::move(scene)); }

void Session::adopt(Scene fresh) {
    m_camera = fresh.camera;
    m_depth_cue = fresh.depth_cue;
    if (!m_scene) {
        m_scene = std::make_unique<Scene>(std::move(fresh));
        m_cache->bind(m_scene.get());
        return;
    }
    // Lights and materials are cheap to read again; only structures built from geometry alone
    // outlive a change, and only when the geometry is equal value for value. The kept
    // structures point into the old arrays, so those stay (moved, not copied).
    if (same_geometry(*m_scene, fresh)) {
        fresh.spheres = std::move(m_scene->spheres);
        fresh.planes = std::move(m_scene->planes);
        fresh.triangles = std::move(m_scene->triangles);
        m_cache->invalidate(SceneParts::lights | SceneParts::materials);
    } else {
        m_cache->invalidate(SceneParts::all);
    }
    *m_scene = std::move(fresh);
}

void Session::set(const SceneOverride& edit) {
    SceneSource source = m_source;
    source.overrides.push_back(edit);
    std::vector<std::string> warnings;
    const auto start = Clock::now();
    double grown = 0;
    Scene scene = load_measured(source, warnings, grown);
    m_load_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    m_source = std::move(source);
    m_warnings = std::move(warnings);
    adopt(std::move(scene));
    m_scene_memory.reset();
    m_scene_memory.emplace(grown);
}

void Session::replace_scene(Scene scene) { adopt(std::move(scene)); }

Camera Session::camera_for(const RenderRequest& request) const {
    return resized_camera(request.camera.value_or(m_camera), request.width, request.height);
}

const Scene& Session::scene_for(const RenderRequest& request, std::optional<Scene>& changed) {
    m_scene->camera = camera_for(request);
    m_scene->depth_cue = m_depth_cue;
    if (request.depth_cue) {
        // --depth-cue overrides the scene's distances and keeps its colour and blur.
        DepthCue cue = m_depth_cue.value_or(DepthCue{});
        cue.near = request.depth_cue->first;
        cue.far = request.depth_cue->second;
        m_scene->depth_cue = cue;
    }
    const std::optional<ShadingTerm> term = shading_term_of(request.aov);
    if (request.tessellation <= 0 && !term) return *m_scene;
    changed.emplace(*m_scene);
    if (request.tessellation > 0)
        for (Sphere& s : changed->spheres) s.segments = static_cast<uint32_t>(request.tessellation);
    if (term) changed = isolate_shading_term(std::move(*changed), *term);
    return *changed;
}

Scene Session::scene_as_rendered(const RenderRequest& request) {
    std::optional<Scene> changed;
    const Scene& scene = scene_for(request, changed);
    return changed ? std::move(*changed) : scene;
}

std::string Session::explain(const RenderRequest& request, const ExplainStep& step) {
    const Method& method = method_named(request.method);
    const ExplainViews& views = method.explain;
    if (!has_explain_view(method))
        throw InputError(fmt::format("explain: {} has no explain view", method.name));
    const MemoryScope scope;  // the scene's copy, the image and the method's own records
    const Scene scene = scene_as_rendered(request);
    check_image_memory(scene.camera);
    const MethodSettings& own = request.options;
    // A method's view takes the step asked for: a pixel, a row, or the whole run.
    if (views.pixel && (step.pixel || !views.row)) {
        if (!step.pixel)
            throw InputError(fmt::format("explain -m {} needs --pixel X,Y", method.name));
        return views.pixel(scene, own, step.pixel->first, step.pixel->second);
    }
    if (views.row && (step.row || !views.whole)) {
        if (!step.row) throw InputError(fmt::format("explain -m {} needs --row Y", method.name));
        return views.row(scene, own, *step.row);
    }
    return views.whole(scene, own);
}

RenderResult Session::render(const RenderRequest& request) {
    // Every buffer this render makes counts against the limit with the next (and the scene's).
    const MemoryScope scope;
    const Method& method = method_named(request.method);
    check_aov(method, request.aov);
    check_image_memory(camera_for(request));
    std::optional<Scene> changed;
    const Scene& scene = scene_for(request, changed);
    const ThreadLimit thread_limit(request.threads);
    RenderResult result;
    RenderControl control;
    const auto start = Clock::now();
    {
        const RenderWatch watch(request, control);
        if (is_algorithm_aov(request.aov)) {
            AlgorithmAov a = algorithm_aov(scene, method, request.aov, request.options,
                                           request.algorithm_counts);
            result.algorithm_picture = std::move(a.image);
            result.algorithm_summary = std::move(a.summary);
        } else {
            if (method.warnings) result.warnings = method.warnings(scene);
            RenderSettings settings;
            if (method.shares_tiles) control.share = request.tile_share;
            settings.control = &control;
            settings.stats = result.stats.get();
            settings.aov_buffers = !is_colour_aov(request.aov) || request.wireframe_overlay;
            settings.cache = m_cache.get();
            const FilmFormat film = request.wireframe_overlay ? FilmFormat::linear : request.film;
            result.framebuffer =
                render_scene(method, scene, Film(scene.camera, film), settings, request.options);
        }
    }
    if (control.cancel.load() || cancel_requested()) throw Interrupted();
    if (result.stats->depth_sort_gave_up.load())
        result.warnings.push_back(fmt::format(
            "the depth sort stopped cutting polygons after {} cuts: they pierce one another so "
            "much that ordering them all needs cuts quadratic in their number, so some pixels "
            "may show a farther polygon (-m zbuffer resolves every pixel exactly)",
            result.stats->depth_sort_splits.load()));
    if (request.wireframe_overlay && !is_algorithm_aov(request.aov)) {
        LineSettings lines;
        lines.triangle_edges = true;
        lines.cull_back_faces = request.options.raster.cull_back_faces;
        overlay_wireframe(scene, lines, k_overlay_colour, result.framebuffer.depth,
                          result.framebuffer.film.linear());
    }
    result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return result;
}

LineDrawing Session::draw(const RenderRequest& request) {
    const Method& method = method_named(request.method);
    if (!method.draw)
        throw InputError(fmt::format("method {} draws no lines (methods that do: {})", method.name,
                                     drawing_methods()));
    const MemoryScope scope;
    std::optional<Scene> changed;
    const Scene& scene = scene_for(request, changed);
    const ThreadLimit thread_limit(request.threads);
    return draw_scene(method, scene, request.options);
}

}  // namespace hikari
