// The hikari command line: `hikari render [SCENE] [options]`, `hikari bench B1|B2 --mesh FILE`,
// `hikari bench B5`, `hikari gallery`, `hikari compare A B`, `hikari explain SCENE -m METHOD`.

#include <unistd.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <thread>
#include <tuple>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tbb/global_control.h>
#include <CLI/CLI.hpp>

#include "gallery.h"
#include "hikari/bench/bench_runner.h"
#include "hikari/bench/path_bench.h"
#include "hikari/bench/raster_bench.h"
#include "hikari/core/cancel.h"
#include "hikari/core/error.h"
#include "hikari/core/memory_budget.h"
#include "hikari/explain/algorithm_aovs.h"
#include "hikari/explain/explain.h"
#include "hikari/frame/aov_picture.h"
#include "hikari/frame/image_compare.h"
#include "hikari/frame/tone_map.h"
#include "hikari/io/files/atomic_file.h"
#include "hikari/io/files/read_file.h"
#include "hikari/io/images/image_format.h"
#include "hikari/io/images/image_read.h"
#include "hikari/io/images/image_write.h"
#include "hikari/io/images/svg_write.h"
#include "hikari/io/images/xlsx_write.h"
#include "hikari/io/models/model_file.h"
#include "hikari/io/models/model_scene.h"
#include "hikari/io/scene/json_reader.h"
#include "hikari/io/scene/scene_json.h"
#include "hikari/methods/registry.h"
#include "hikari/raster/lines/wireframe.h"
#include "hikari/shading/shading_terms.h"
#include "hikari/version.h"
#include "info.h"

namespace {

using namespace hikari;
using Clock = std::chrono::steady_clock;

/// Exit statuses: 1 for bad input or a failed render, 2 for command-line usage errors, 128 + the
/// signal's number when SIGINT (130) or SIGTERM (143) stops the run.
constexpr int k_exit_input_error = 1;
constexpr int k_exit_usage_error = 2;

/// A command-line mistake found after parsing (an output that cannot be written): printed as
/// `hikari: error: <message>`, exit status 2.
class UsageError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// `--wireframe-overlay`'s line colour: near black, a figure's ink.
constexpr Vec3 k_overlay_colour{0.02f, 0.02f, 0.02f};

/// `--tonemap`'s words.
constexpr Choice<ToneMap> k_tone_map_choices[] = {
    {"clamp", ToneMap::clamp}, {"reinhard", ToneMap::reinhard}, {"aces", ToneMap::aces}};

/// `--aov`'s words.
constexpr Choice<Aov> k_aov_choices[] = {
    {"color", Aov::color},       {"depth", Aov::depth},       {"id", Aov::id},
    {"normal", Aov::normal},     {"ambient", Aov::ambient},   {"diffuse", Aov::diffuse},
    {"specular", Aov::specular}, {"overdraw", Aov::overdraw}, {"paint-order", Aov::paint_order},
    {"spans", Aov::spans},       {"culled", Aov::culled}};

/// The shading term an --aov word names, if it names one.
std::optional<ShadingTerm> shading_term_of(Aov aov) {
    if (aov == Aov::ambient) return ShadingTerm::ambient;
    if (aov == Aov::diffuse) return ShadingTerm::diffuse;
    if (aov == Aov::specular) return ShadingTerm::specular;
    return std::nullopt;
}

struct RenderOptions {
    std::string scene_file;  // empty: the built-in assignment scene
    std::string output;
    std::vector<std::string> methods{"raytrace"};  // -m a,b,c: each in turn, one scene load
    Aov aov = Aov::color;
    int width = 0, height = 0;
    int threads = 0;
    double max_memory_gib = 0;
    double max_input_gib = 0;  ///< --max-input-size; 0 = each kind's default
    bool quiet = false;
    bool stats = false;
    bool print_matrices = false;
    bool wireframe_overlay = false;
    int tessellation = 0;            // --tessellation N: every sphere's segments; 0: the scene's
    std::vector<float> depth_cue;    // --depth-cue NEAR,FAR; empty: the scene's own, if any
    std::vector<float> depth_range;  // --depth-range NEAR,FAR; empty: the visible range
    std::vector<SceneOverride> overrides;  // --set PATH=VALUE, in order
    bool ground = false;                   // --ground: a plane under a model file
    std::vector<float> camera_from;        // --camera-from X,Y,Z; empty: the scene's or framing
    std::vector<float> look_at;            // --look-at X,Y,Z
    float crease_angle = -1;               // --crease-angle DEG; negative: each mesh's own
    MethodSettings own;                    // every method option; the chosen method reads its part
    std::vector<std::string> notes;        // warnings found while checking the command line
    float exposure = 0.0f;                 // --exposure EV: colour × 2^EV in every format
    ToneMap tone_map = ToneMap::clamp;     // --tonemap: for the formats of display values
    int bit_depth = 8;                     // --bit-depth: 16 for .png and .ppm
};

RenderControl g_control;
// Lock-free atomics are safe to touch from a signal handler.
std::atomic<int> g_signal_count{0};
std::atomic<int> g_first_signal{0};  // SIGINT or SIGTERM, the first one received; 0: none
std::atomic<bool> g_interrupt_reported{false};

/// 128 + the signal that stopped the run (130 for SIGINT, 143 for SIGTERM), as a shell reports
/// a process killed by it.
int interrupted_status() noexcept {
    const int sig = g_first_signal.load();
    return 128 + (sig != 0 ? sig : SIGINT);
}

/// Prints `hikari: interrupted` on stderr, once whichever path gets there first (the render's
/// unwinding or the handler's fallback). Async-signal-safe: write(2) on a constant.
void report_interrupted() noexcept {
    if (g_interrupt_reported.exchange(true)) return;
    static constexpr char k_line[] = "hikari: interrupted\n";
    [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, k_line, sizeof k_line - 1);
}

// The first SIGINT or SIGTERM asks every stage to stop (the render, and through core/cancel.h
// the loaders, the BVH build and the encoders, which then unwind writing nothing), and arms a
// one-second alarm in case the running stage does not poll (a codec inside a library call). On
// a second signal, or when the alarm rings, leave at once, removing any half-written temporary
// file. Either way the status is 128 + the first signal and the one line is printed.
extern "C" void exit_now(int) {
    remove_pending_temporary_files();
    report_interrupted();
    _exit(interrupted_status());
}

extern "C" void on_interrupt(int sig) {
    int none = 0;
    g_first_signal.compare_exchange_strong(none, sig);
    g_control.cancel.store(true);
    request_cancel();
    if (g_signal_count.fetch_add(1) > 0) exit_now(sig);
    alarm(1);
}

/// Installed first thing, so that a signal at any stage (parsing included) ends the same way.
void install_signal_handlers() {
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    action.sa_handler = exit_now;
    sigaction(SIGALRM, &action, nullptr);
}

/// Prints a progress line on stderr, once a stage has taken a second, when stderr is a terminal:
/// for a render a bar with the percentage done, the rate in pixels per second and the time left
/// (`pixels` > 0); for a load (`pixels` = 0, no measure of the work) the time so far.
class ProgressReporter {
  public:
    ProgressReporter(bool enabled, std::string stage, double pixels) {
        if (!enabled || !isatty(STDERR_FILENO)) return;
        m_thread = std::jthread([stage = std::move(stage), pixels](const std::stop_token& stop) {
            const auto start = Clock::now();
            bool shown = false;
            while (!stop.stop_requested()) {
                std::this_thread::sleep_for(std::chrono::milliseconds(100));
                const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
                if (elapsed < 1.0) continue;
                const uint64_t total = g_control.work_total.load();
                if (pixels <= 0.0 || total == 0) {
                    fmt::print(stderr, "\rhikari: {} ... {:.1f} s ", stage, elapsed);
                } else {
                    const double done = static_cast<double>(g_control.work_done.load()) / total;
                    const double eta = done > 0 ? elapsed * (1.0 - done) / done : 0.0;
                    constexpr int k_bar = 24;
                    const int filled = std::clamp(static_cast<int>(done * k_bar), 0, k_bar);
                    fmt::print(stderr,
                               "\rhikari: {} [{}{}] {:5.1f}%  {:.2f} Mpixel/s  {:.1f} s elapsed, "
                               "~{:.1f} s left ",
                               stage, std::string(filled, '#'), std::string(k_bar - filled, '.'),
                               100.0 * done, 1e-6 * done * pixels / elapsed, elapsed, eta);
                }
                shown = true;
            }
            if (shown) fmt::print(stderr, "\r\033[K");
        });
    }

  private:
    std::jthread m_thread;
};

/// Applies --width / --height; one alone keeps the camera's aspect ratio.
void resize_camera(Camera& camera, int width, int height) {
    if (width > 0 && height == 0)
        height = std::max(1, static_cast<int>(std::lround(static_cast<double>(width) *
                                                          camera.height / camera.width)));
    if (height > 0 && width == 0)
        width = std::max(1, static_cast<int>(std::lround(static_cast<double>(height) *
                                                         camera.width / camera.height)));
    if (width > 0) camera.width = width;
    if (height > 0) camera.height = height;
}

/// Refuses renders whose buffers would not fit in the memory limit, before allocating any.
void check_memory(const Camera& camera) {
    const double pixels = static_cast<double>(camera.width) * camera.height;
    // colour + depth + id + normal in the framebuffer, one more image for the output.
    check_memory_need(pixels * (sizeof(Vec3) * 3 + sizeof(float) + sizeof(uint32_t)),
                      fmt::format("a {}x{} image", camera.width, camera.height));
}

/// The output of `method`: `-o` as given for one method; for several, `-o NAME.EXT` becomes
/// NAME-<method>.EXT. Without -o, `<scene>.png` for the default method alone, else
/// `<scene>-<method>.png` (so rendering a scene by several methods keeps every picture), with
/// `-<aov>` added for a buffer other than colour.
std::string output_for(const RenderOptions& o, std::string_view method) {
    const bool several = o.methods.size() > 1;
    if (!o.output.empty()) {
        if (!several) return o.output;
        const std::filesystem::path out(o.output);
        return (out.parent_path() /
                (out.stem().string() + "-" + std::string(method) + out.extension().string()))
            .string();
    }
    const std::string stem =
        o.scene_file.empty() ? "assignment" : std::filesystem::path(o.scene_file).stem().string();
    const std::string suffix =
        !several && method == methods().front().name ? "" : "-" + std::string(method);
    const std::string_view aov = choice_name<Aov>(k_aov_choices, o.aov);
    return stem + suffix + (o.aov == Aov::color ? "" : "-" + std::string(aov)) + ".png";
}

/// A file the render reads, which its output must not replace, and what it is to the render.
struct RenderInput {
    std::filesystem::path file;
    std::string role;  ///< "the scene file", "the model file", "a file the scene reads"
};

/// Every string member "file" of a scene's JSON (meshes, textures, environment maps), relative
/// to `base_dir`; `depth` bounds the walk on hostile nesting.
void collect_named_files(const nlohmann::json& v, const std::filesystem::path& base_dir,
                         std::vector<RenderInput>& out, int depth = 0) {
    if (depth > 64 || !v.is_structured()) return;
    for (auto it = v.begin(); it != v.end(); ++it) {
        if (v.is_object() && it.key() == "file" && it->is_string())
            out.push_back({base_dir / it->get<std::string>(), "a file the scene reads"});
        else
            collect_named_files(*it, base_dir, out, depth + 1);
    }
}

/// The files a render of `scene_file` reads: the scene (or model) file, and the files the
/// scene names. A scene that cannot be read or parsed names none here: its loader reports it.
std::vector<RenderInput> render_inputs(const std::string& scene_file) {
    if (scene_file.empty()) return {};
    const bool model = is_model_file(scene_file);
    std::vector<RenderInput> inputs{{scene_file, model ? "the model file" : "the scene file"}};
    if (model) return inputs;
    try {
        const nlohmann::json json = parse_json(read_file_bytes(scene_file), scene_file);
        collect_named_files(json, std::filesystem::path(scene_file).parent_path(), inputs);
    } catch (const std::exception&) {  // not readable or not JSON: the load says why
    }
    return inputs;
}

/// Refuses, before any work is done, an output the render could not be written to (usage
/// errors, exit 2: a directory, an unknown extension, a missing or read-only directory, a name
/// too long), or that is a file the render reads (a scene named `scene.png` rendered without
/// -o, `render bunny.ply -o bunny.ply`, a scene's mesh or texture). Then removes the
/// temporaries that a killed earlier run left beside it (io/atomic_file.h).
void check_output_path(const std::filesystem::path& output, std::span<const RenderInput> inputs) {
    std::error_code ec;
    if (std::filesystem::is_directory(output, ec))
        throw UsageError(
            fmt::format("{}: is a directory; name an image file to write", output.string()));
    if (!is_supported_image_extension(output) && !is_svg_path(output))
        throw UsageError(fmt::format(
            "{}: unknown output format {} (supported: {}, and .svg for wireframe and hiddenline)",
            output.string(),
            output.has_extension() ? "'" + output.extension().string() + "'" : "(no extension)",
            k_writable_image_extensions));
    const std::filesystem::path dir = output.has_parent_path() ? output.parent_path() : ".";
    if (!std::filesystem::is_directory(dir, ec))
        throw UsageError(fmt::format(
            "{}: cannot write: the directory {} {}", output.string(), dir.string(),
            std::filesystem::exists(dir, ec) ? "is not a directory" : "does not exist"));
    if (::access(dir.c_str(), W_OK) != 0)
        throw UsageError(fmt::format("{}: cannot write: the directory {} is not writable",
                                     output.string(), dir.string()));
    const long name_max = ::pathconf(dir.c_str(), _PC_NAME_MAX);
    if (const size_t length = output.filename().string().size();
        name_max > 0 && length > static_cast<size_t>(name_max))
        throw UsageError(
            fmt::format("{}: cannot write: the file name is {} bytes long; the "
                        "file system allows {}",
                        output.string(), length, name_max));
    for (const RenderInput& input : inputs) {
        if (std::filesystem::equivalent(output, input.file, ec))
            throw UsageError(fmt::format(
                "{}: refusing to overwrite {}{} with the render", output.string(), input.role,
                input.role.starts_with("the ") ? "" : " (" + input.file.string() + ")"));
    }
    remove_stale_temporary_files(output);
}

/// Refuses, before rendering, a spreadsheet output larger than a sheet holds.
void check_spreadsheet_size(const std::filesystem::path& output, const Camera& camera) {
    if (image_format_from_extension(output) != ImageFormat::Xlsx) return;
    if (camera.width > k_xlsx_max_columns || camera.height > k_xlsx_max_rows)
        throw InputError(fmt::format(
            "{}: a {}x{} image does not fit a spreadsheet (at most {} columns and {} rows)",
            output.string(), camera.width, camera.height, k_xlsx_max_columns, k_xlsx_max_rows));
}

/// Wall times of run_render's phases, for `--stats`.
struct PhaseTimes {
    double load = 0;    ///< reading and checking the scene, in seconds
    double render = 0;  ///< the method's render (BVH build included)
    double write = 0;   ///< encoding and writing the output file
};

/// `--stats`: phase times, rays per second and the BVH's figures, on stderr.
void print_stats(const PhaseTimes& times, const RenderStats& g_stats, std::string_view method) {
    // What raster_fragments counts for each method.
    const std::string_view work_name = method == "zbuffer"     ? "fragments depth-tested"
                                       : method == "scanline"  ? "sample spans"
                                       : method == "depthsort" ? "pixel paints"
                                                               : "pixel paints (naive)";
    const uint64_t rays = g_stats.rays_traced.load();
    fmt::print(stderr, "hikari: stats: load {:.1f} ms, render {:.1f} ms, write {:.1f} ms",
               1e3 * times.load, 1e3 * times.render, 1e3 * times.write);
    if (rays > 0)
        fmt::print(stderr, "; {} rays, {:.2f} Mrays/s", rays, 1e-6 * double(rays) / times.render);
    if (const uint64_t paths = g_stats.paths_traced.load(); paths > 0)
        fmt::print(stderr, "; {} paths, {:.2f} Mpaths/s, {} NaN/Inf samples", paths,
                   1e-6 * double(paths) / times.render, g_stats.bad_samples.load());
    fmt::print(stderr, "\n");
    const uint64_t exact_spheres = g_stats.raster_exact_spheres.load();
    if (const uint64_t in = g_stats.raster_triangles.load(); in > 0 || exact_spheres > 0) {
        const uint64_t covered = g_stats.raster_covered_pixels.load();
        const uint64_t work = g_stats.raster_fragments.load();
        fmt::print(stderr,
                   "hikari: stats: vertex stage: {} triangles in, {} culled (back faces), {} "
                   "clipped away, {} cut by clipping; {} screen triangles\n",
                   in, g_stats.raster_culled.load(), g_stats.raster_clipped_away.load(),
                   g_stats.raster_cut.load(), g_stats.raster_screen_triangles.load());
        if (exact_spheres > 0)
            fmt::print(stderr, "hikari: stats: {} exact sphere(s) drawn per pixel\n",
                       exact_spheres);
        fmt::print(stderr, "hikari: stats: hidden surfaces: {} pixels covered", covered);
        if (work > 0)
            fmt::print(stderr, "; {} {} ({:.2f} per covered pixel)", work, work_name,
                       covered ? double(work) / double(covered) : 0.0);
        if (const uint64_t splits = g_stats.depth_sort_splits.load();
            splits > 0 || work_name == "pixel paints")
            fmt::print(stderr, "; {} depth-sort splits", splits);
        fmt::print(stderr, "\n");
    }
    const uint64_t triangles = g_stats.bvh_triangles.load();
    if (triangles > 0)
        fmt::print(stderr,
                   "hikari: stats: BVH {} triangles, {} nodes (8-wide), {:.1f} bytes/triangle, "
                   "built in {:.1f} ms, {} kernels\n",
                   triangles, g_stats.bvh_nodes.load(),
                   double(g_stats.bvh_bytes.load()) / double(triangles),
                   1e-3 * double(g_stats.bvh_build_us.load()), simd_level_name(best_simd_level()));
    if (const uint64_t spheres = g_stats.bvh_spheres.load(); spheres > 0)
        fmt::print(stderr,
                   "hikari: stats: sphere BVH {} spheres, {} nodes (8-wide), {:.1f} bytes/sphere\n",
                   spheres, g_stats.bvh_sphere_nodes.load(),
                   double(g_stats.bvh_sphere_bytes.load()) / double(spheres));
}

/// The scene the options name, at the image size they ask for, within the memory limit.
Scene load_render_scene(const RenderOptions& o) {
    std::vector<std::string> warnings;
    if (o.max_memory_gib > 0) set_memory_limit(o.max_memory_gib * (1 << 30));
    if (o.max_input_gib > 0)
        set_max_input_size(static_cast<std::uintmax_t>(o.max_input_gib * (1 << 30)));
    // --camera-from and --look-at edit the document like --set, before a far scene is rebased.
    std::vector<SceneOverride> overrides = o.overrides;
    if (!o.camera_from.empty()) overrides.push_back({"--camera-from", "camera.eye", o.camera_from});
    if (!o.look_at.empty()) overrides.push_back({"--look-at", "camera.look_at", o.look_at});
    SceneLoadOptions load(overrides);
    if (o.crease_angle >= 0.0f) load.crease_angle = o.crease_angle;
    const bool model = is_model_file(o.scene_file);
    Scene scene;
    {
        ProgressReporter progress(!o.quiet, "loading " + o.scene_file, 0.0);
        scene = o.scene_file.empty() ? load_default_scene(load)
                : model ? load_model_scene(o.scene_file, {.ground = o.ground, .mesh = {}}, warnings,
                                           load)
                        : load_scene_file(o.scene_file, warnings, load);
    }
    if (o.ground && !model)
        warnings.emplace_back("--ground adds a plane under a model file; the scene has its own");
    for (const std::string& w : warnings) fmt::print(stderr, "hikari: warning: {}\n", w);
    resize_camera(scene.camera, o.width, o.height);
    if (o.tessellation > 0)
        for (Sphere& s : scene.spheres) s.segments = static_cast<uint32_t>(o.tessellation);
    if (const std::optional<ShadingTerm> term = shading_term_of(o.aov))
        scene = isolate_shading_term(std::move(scene), *term);
    if (!o.depth_cue.empty()) {
        // --depth-cue overrides the scene's distances and keeps its colour and blur.
        DepthCue cue = scene.depth_cue.value_or(DepthCue{});
        cue.near = o.depth_cue[0];
        cue.far = o.depth_cue[1];
        scene.depth_cue = cue;
    }
    check_memory(scene.camera);
    return scene;
}

/// Whether `output` holds display values (PNG, JPEG, PPM, a spreadsheet), not linear floats.
bool is_picture_file(const std::string& output) {
    const std::optional<ImageFormat> format = image_format_from_extension(output);
    return format && is_low_dynamic_range(*format);
}

/// The film for `output`: 8-bit sRGB where the file keeps only that (the colour, neither exposed
/// nor tone mapped, in an 8-bit PNG, JPEG, PPM or spreadsheet), else linear floats.
Film output_film(const Camera& camera, const std::string& output, const RenderOptions& o) {
    const bool srgb8 = is_colour_aov(o.aov) && is_picture_file(output) && o.bit_depth == 8 &&
                       o.exposure == 0.0f && o.tone_map == ToneMap::clamp;
    return Film(camera, srgb8 ? FilmFormat::srgb8 : FilmFormat::linear);
}

/// Writes a colour render to `output` developed as --exposure and --tonemap ask (the tone map
/// only where the file holds display values; float files keep radiance), at --bit-depth.
void write_colour(const std::string& output, Image colour, const RenderOptions& o) {
    expose_and_tone_map(colour, o.exposure, is_picture_file(output) ? o.tone_map : ToneMap::clamp);
    write_image(output, colour, ImageWriteSettings{o.bit_depth});
}

/// Writes the buffer `aov` of a finished render to `output` (unless the render was interrupted):
/// an AOV buffer as a picture (frame/aov_picture.h) where the file holds display values, else as
/// its values; a colour render developed by write_colour.
void write_output(const std::string& output, Framebuffer&& fb, Aov aov,
                  std::optional<DepthRange> depth_range, const RenderOptions& o) {
    if (g_control.cancel.load()) throw Interrupted();
    const ImageWriteSettings settings{o.bit_depth};
    if (fb.film.format() == FilmFormat::srgb8)
        write_image(output, fb.film.srgb8());
    else if (is_colour_aov(aov))
        write_colour(output, aov_image(std::move(fb), aov), o);
    else if (is_picture_file(output))
        write_image(output, aov_picture(fb, aov, depth_range), settings);
    else
        write_image(output, aov_image(std::move(fb), aov), settings);
}

/// `--progressive`: the image so far written over `output` (atomically, as every image is: a
/// viewer watching the file sees the old image or the new one, never half of one).
void write_progressive_snapshot(const std::string& output, const Image& mean,
                                const RenderOptions& o) {
    if (g_control.cancel.load()) return;
    write_colour(output, mean, o);
}

/// Refuses, before any work is done, an SVG output that the method or --aov cannot give: a
/// command-line mistake (exit 2), like any other -o mistake.
void check_svg_output(const std::string& output, const Method& method, Aov aov) {
    if (!is_svg_path(output)) return;
    if (!method.draw)
        throw UsageError(
            fmt::format("{}: SVG output is for the line methods (wireframe, "
                        "hiddenline); method {} draws no lines",
                        output, method.name));
    if (aov != Aov::color)
        throw UsageError(
            fmt::format("{}: SVG output holds the lines' colours; --aov {} needs an "
                        "image format",
                        output, choice_name<Aov>(k_aov_choices, aov)));
}

/// Refuses, before any work is done, a shading term of a method whose colour is not the
/// lecture's sum of terms (path tracing, the line drawings).
void check_aov_method(const Method& method, Aov aov) {
    if (is_algorithm_aov(aov) && !has_algorithm_aov(method.name, aov))
        throw CLI::ValidationError(fmt::format("--aov {} shows the work of {}, not of method {}",
                                               choice_name<Aov>(k_aov_choices, aov),
                                               methods_with_algorithm_aov(aov), method.name));
    if (!shading_term_of(aov) || method.shading_terms) return;
    throw CLI::ValidationError(
        fmt::format("--aov {}: method {} does not shade by ambient + diffuse + specular (Fig "
                    "4.29), so it has no such term (methods that do: {})",
                    choice_name<Aov>(k_aov_choices, aov), method.name, shading_term_methods()));
}

/// The line method's drawing written as SVG (`-o drawing.svg`).
int run_drawing(const RenderOptions& o, const Method& method, const std::string& output) {
    const Scene scene = load_render_scene(o);
    std::optional<tbb::global_control> thread_limit;
    if (o.threads > 0)
        thread_limit.emplace(tbb::global_control::max_allowed_parallelism,
                             static_cast<size_t>(o.threads));
    const auto start = Clock::now();
    const LineDrawing drawing = draw_scene(method, scene, o.own);
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (g_control.cancel.load()) throw Interrupted();
    write_svg(output, drawing);
    if (!o.quiet)
        fmt::print(stderr, "hikari: wrote {} ({}x{}, {}, {} segments, {:.3f} s)\n", output,
                   drawing.width, drawing.height, method.name, drawing.segments.size(), seconds);
    return 0;
}

/// The line that ends a render: what was written, the scene's size and where the time went.
void print_summary(const std::string& output, int width, int height, const Method& method,
                   const Scene& scene, const PhaseTimes& times, const RenderStats& stats) {
    std::string text =
        fmt::format("hikari: wrote {} ({}x{}, {}; ", output, width, height, method.name);
    const size_t triangles = scene.triangles.indices.size();
    text += fmt::format("{} triangle{}", triangles, triangles == 1 ? "" : "s");
    if (const size_t spheres = scene.spheres.size(); spheres > 0)
        text += fmt::format(", {} sphere{}", spheres, spheres == 1 ? "" : "s");
    text += fmt::format("; load {:.3f} s", times.load);
    if (const uint64_t us = stats.bvh_build_us.load(); us > 0)
        text += fmt::format(", BVH {:.1f} ms", 1e-3 * double(us));
    text += fmt::format(", render {:.3f} s)", times.render);
    fmt::print(stderr, "{}\n", text);
}

/// One method's render of the loaded scene into `output`. `load_seconds`: the time spent loading,
/// for --stats.
void render_with(const RenderOptions& o, const Scene& scene, const Method& method,
                 const std::string& output, double load_seconds) {
    if (is_algorithm_aov(o.aov)) {
        const bool raw = !is_picture_file(output);
        const auto start = Clock::now();
        const AlgorithmAov a = algorithm_aov(scene, method, o.aov, o.own, raw);
        if (g_control.cancel.load()) throw Interrupted();
        write_image(output, a.image, ImageWriteSettings{o.bit_depth});
        if (!o.quiet)
            fmt::print(stderr, "hikari: wrote {} ({}x{}, {}, {:.3f} s)\nhikari: {}\n", output,
                       a.image.width, a.image.height, method.name,
                       std::chrono::duration<double>(Clock::now() - start).count(), a.summary);
        return;
    }
    if (method.warnings)
        for (const std::string& w : method.warnings(scene))
            fmt::print(stderr, "hikari: warning: {}\n", w);
    MethodSettings own = o.own;
    if (own.path.progressive_seconds > 0.0f && o.aov == Aov::color)
        own.path.snapshot = [&output, &o](const Image& mean, int) {
            write_progressive_snapshot(output, mean, o);
        };
    RenderSettings settings;
    RenderStats stats;
    g_control.work_done = 0;
    g_control.work_total = 0;
    settings.control = &g_control;
    settings.stats = &stats;
    settings.aov_buffers = !is_colour_aov(o.aov) || o.wireframe_overlay;

    std::optional<tbb::global_control> thread_limit;
    if (o.threads > 0)
        thread_limit.emplace(tbb::global_control::max_allowed_parallelism,
                             static_cast<size_t>(o.threads));
    const auto start = Clock::now();
    PhaseTimes times;
    times.load = load_seconds;
    Framebuffer fb;
    {
        ProgressReporter progress(!o.quiet, "rendering",
                                  double(scene.camera.width) * scene.camera.height);
        fb = render_scene(method, scene,
                          o.wireframe_overlay ? Film(scene.camera, FilmFormat::linear)
                                              : output_film(scene.camera, output, o),
                          settings, own);
    }
    if (o.wireframe_overlay && !g_control.cancel.load()) {
        LineSettings lines;
        lines.triangle_edges = true;
        lines.cull_back_faces = own.raster.cull_back_faces;
        overlay_wireframe(scene, lines, k_overlay_colour, fb.depth, fb.film.linear());
    }
    const auto rendered = Clock::now();
    times.render = std::chrono::duration<double>(rendered - start).count();
    const int width = fb.width(), height = fb.height();
    write_output(output, std::move(fb), o.aov,
                 o.depth_range.empty()
                     ? std::nullopt
                     : std::optional(DepthRange{o.depth_range[0], o.depth_range[1]}),
                 o);
    times.write = std::chrono::duration<double>(Clock::now() - rendered).count();
    if (!o.quiet) print_summary(output, width, height, method, scene, times, stats);
    if (const uint64_t bad = stats.bad_samples.load(); bad > 0)
        fmt::print(stderr,
                   "hikari: warning: {} samples were NaN or infinite and were left out of the "
                   "image (their pixels average the other samples as if these were black)\n",
                   bad);
    if (o.stats) print_stats(times, stats, method.name);
}

/// `hikari render`: every method asked for, in turn, on one load of the scene. Every output is
/// checked before any work is done.
int run_render(const RenderOptions& o) {
    const auto load_start = Clock::now();
    std::vector<std::pair<const Method*, std::string>> runs;
    const std::vector<RenderInput> inputs = render_inputs(o.scene_file);
    for (const std::string& name : o.methods) {
        const Method& method = *find_method(name);  // checked by the parser
        const std::string output = output_for(o, name);
        check_output_path(output, inputs);
        check_svg_output(output, method, o.aov);
        runs.emplace_back(&method, output);
    }
    if (is_svg_path(runs.front().second)) {
        for (const auto& [method, output] : runs) run_drawing(o, *method, output);
        return 0;
    }
    for (const std::string& note : o.notes) fmt::print(stderr, "hikari: warning: {}\n", note);
    const Scene scene = load_render_scene(o);
    for (const auto& [method, output] : runs) check_spreadsheet_size(output, scene.camera);
    if (o.print_matrices) fmt::print("{}", explain_matrices(scene, o.own.raster));
    const double load_seconds = std::chrono::duration<double>(Clock::now() - load_start).count();
    for (const auto& [method, output] : runs) render_with(o, scene, *method, output, load_seconds);
    return 0;
}

/// `--simd`'s words; auto (nullopt) is the best level this CPU has.
constexpr Choice<std::optional<SimdLevel>> k_simd_choices[] = {{"auto", std::nullopt},
                                                               {"portable", SimdLevel::portable},
                                                               {"avx2", SimdLevel::avx2},
                                                               {"avx512", SimdLevel::avx512}};

struct BenchOptions {
    std::string bench;
    std::string mesh;
    std::string scene;  // B5; empty: the repository's scenes/bench/cornell.json
    std::optional<SimdLevel> simd;
    int threads = 1;
    std::optional<int> repetitions;  // default: 5 for B1 and B2, 3 for B5 (the SPEC's)
    bool packets = false;
    bool shadow = false;  // B4
    std::string output;   // B4: the last frame
};

/// `hikari bench B5`: the path tracer on the Cornell box (SPEC §7), one JSON object on stdout.
int run_path_bench_command(const BenchOptions& o) {
    if (!o.mesh.empty() || o.packets || o.simd || o.shadow || !o.output.empty())
        throw InputError(
            "B5 renders a scene: --mesh, --packets, --simd, --shadow and --output are for B1, B2 "
            "and B4");
    const std::string file =
        o.scene.empty() ? std::string(HIKARI_SOURCE_DIR) + "/scenes/bench/cornell.json" : o.scene;
    std::vector<std::string> warnings;
    const Scene scene = load_scene_file(file, warnings);
    for (const std::string& w : warnings) fmt::print(stderr, "hikari: warning: {}\n", w);
    const tbb::global_control thread_limit(tbb::global_control::max_allowed_parallelism,
                                           static_cast<size_t>(o.threads));
    PathBenchSettings settings;
    settings.threads = o.threads;
    settings.repetitions = o.repetitions.value_or(settings.repetitions);
    fmt::print("{}\n", run_path_bench(scene, settings).to_json());
    return 0;
}

/// The kernel `--simd` asks for, or `fallback` (the best this CPU has) for auto; an error when
/// this CPU cannot run the one asked for.
SimdLevel chosen_simd(std::optional<SimdLevel> asked, SimdLevel fallback) {
    if (!asked) return fallback;
    if (!simd_level_supported(*asked))
        throw InputError(fmt::format("this CPU cannot run --simd {}", simd_level_name(*asked)));
    return *asked;
}

/// `hikari bench B4`: the raster frame of SPEC §6, one JSON object on stdout.
int run_raster_bench_command(const BenchOptions& o) {
    if (o.packets || !o.scene.empty())
        throw InputError("B4 draws a mesh: --packets and --scene are for B1 and B5");
    if (!o.output.empty() && !is_supported_image_extension(o.output))
        throw InputError(fmt::format("{}: unsupported output format (use {})", o.output,
                                     k_writable_image_extensions));
    RasterBenchSettings settings;
    settings.threads = o.threads;
    settings.shadow = o.shadow;
    settings.timed_frames = o.repetitions.value_or(settings.timed_frames);
    settings.simd = chosen_simd(o.simd, settings.simd);
    const BenchMesh mesh = load_bench_mesh(o.mesh);
    const tbb::global_control thread_limit(tbb::global_control::max_allowed_parallelism,
                                           static_cast<size_t>(o.threads));
    Srgb8Image image;
    const RasterBenchResult result =
        run_raster_bench(mesh, std::filesystem::path(o.mesh).stem().string(), settings, &image);
    if (!o.output.empty()) write_image(o.output, image);
    fmt::print("{}\n", result.to_json());
    return 0;
}

/// `hikari bench`: one JSON object on stdout (SPEC's B1, B2 or B4 on one mesh, or B5).
int run_bench_command(const BenchOptions& o) {
    if (o.bench == "B5") return run_path_bench_command(o);
    if (o.bench == "B4") return run_raster_bench_command(o);
    if (o.shadow || !o.output.empty()) throw InputError("--shadow and --output are for B4");
    if (!o.scene.empty()) throw InputError("--scene is for B5");
    BenchSettings settings;
    settings.bench = o.bench;
    settings.threads = o.threads;
    settings.repetitions = o.repetitions.value_or(settings.repetitions);
    settings.packets = o.packets;
    if (o.packets && o.bench != "B1") throw InputError("--packets is for B1 only");
    settings.simd = chosen_simd(o.simd, settings.simd);
    const BenchMesh mesh = load_bench_mesh(o.mesh);
    const BenchResult result =
        run_bench(mesh, std::filesystem::path(o.mesh).stem().string(), settings);
    fmt::print("{}\n", result.to_json());
    return 0;
}

/// Ends the process once a render's work is done: the streams are flushed, then the system
/// takes back the memory and TBB's worker threads at once (running every destructor first,
/// TBB's joining its workers among them, costs milliseconds and changes nothing).
[[noreturn]] void exit_after_render(int code) {
    std::fflush(nullptr);
    std::_Exit(code);
}

/// Keeps freed memory in the process for reuse instead of handing it back to the system: a
/// loader's or a tracer's growing arrays then refill pages that are already mapped, where each
/// fresh page costs a fault (some 13 us on a virtual machine). Big blocks come from the heap up
/// to glibc's limit for the mmap threshold (32 MiB); bigger ones, and the arrays of
/// core/huge_page_allocator.h, are mapped as before. The OBJ loader's reserve_heap relies on
/// both settings.
void keep_freed_memory() {
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

/// The largest value a real option takes: a float's, so that the value stays finite.
constexpr double k_max_real = std::numeric_limits<float>::max();
/// The smallest positive value, for options that must be above 0.
constexpr double k_least_positive = std::numeric_limits<double>::denorm_min();

/// What a real option in [min, max] expects, in words for its error message.
std::string real_range_words(double min, double max) {
    if (min <= -k_max_real && max >= k_max_real) return "a finite number";
    if (max >= k_max_real) return fmt::format("a number of at least {:g}", min);
    return fmt::format("a number from {:g} to {:g}", min, max);
}

/// The same for --help, after the value's type: `FLOAT:in [0, 180]`.
std::string real_range_label(double min, double max) {
    if (min <= -k_max_real && max >= k_max_real) return "finite";
    if (min > 0 && min < 1e-30) return "> 0";
    if (max >= k_max_real) return fmt::format(">= {:g}", min);
    return fmt::format("in [{:g}, {:g}]", min, max);
}

/// A real option's check: a finite number in [min, max], else the short usage error
/// "--flag: expected <words>" (CLI11's Range lets NaN through and prints its bounds with all
/// 309 digits of a double's largest value).
CLI::Validator real_in(double min, double max, std::string words = {}) {
    if (words.empty()) words = real_range_words(min, max);
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            double value = 0;
            if (CLI::detail::lexical_cast(text, value) && std::isfinite(value) && value >= min &&
                value <= max)
                return {};
            return "expected " + words;
        },
        real_range_label(min, max));
}

/// An integer option's check: a whole number in [min, max], else "--flag: expected a whole
/// number from MIN to MAX".
CLI::Validator whole_in(int min, int max) {
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            int value = 0;
            if (CLI::detail::lexical_cast(text, value) && value >= min && value <= max) return {};
            return fmt::format("expected a whole number from {} to {}", min, max);
        },
        fmt::format("in [{}, {}]", min, max));
}

/// `flag`, taking one of the words of `choices` (the one table that both checks and converts
/// them) into `target`, whose value now is shown as the default.
template <class T>
CLI::Option* add_choice_option(CLI::App& app, std::string_view flag, std::string_view help,
                               std::span<const Choice<T>> choices, T& target) {
    std::vector<std::string> names;
    for (const Choice<T>& c : choices) names.emplace_back(c.name);
    return app
        .add_option_function<std::string>(
            std::string(flag),
            [choices, &target](const std::string& name) {
                target = choice_value(choices, name).value();
            },
            std::string(help))
        ->check(CLI::IsMember(names))
        ->default_str(std::string(choice_name(choices, target)));
}

/// A method option whose value is an integer in a range.
CLI::Option* add_method_option(CLI::App& app, const MethodOption& option,
                               const IntegerOption& integer, MethodSettings& own) {
    return app.add_option(std::string(option.flag), integer.field(own), std::string(option.help))
        ->check(whole_in(integer.min, integer.max))
        ->capture_default_str();
}

/// A method option whose value is an integer in a range, unset unless given.
CLI::Option* add_method_option(CLI::App& app, const MethodOption& option,
                               const OptionalIntegerOption& integer, MethodSettings& own) {
    std::optional<int>& target = integer.field(own);
    return app
        .add_option_function<int>(
            std::string(option.flag), [&target](int value) { target = value; },
            std::string(option.help))
        ->check(whole_in(integer.min, integer.max));
}

/// A method option whose value is a real number in a range.
CLI::Option* add_method_option(CLI::App& app, const MethodOption& option, const RealOption& real,
                               MethodSettings& own) {
    return app.add_option(std::string(option.flag), real.field(own), std::string(option.help))
        ->check(real_in(real.min, real.max))
        ->capture_default_str();
}

/// A method option whose value is a colour R,G,B.
CLI::Option* add_method_option(CLI::App& app, const MethodOption& option, const ColorOption& color,
                               MethodSettings& own) {
    std::optional<Vec3>& target = color.field(own);
    return app
        .add_option_function<std::vector<float>>(
            std::string(option.flag),
            [&target](const std::vector<float>& rgb) { target = Vec3(rgb[0], rgb[1], rgb[2]); },
            std::string(option.help))
        ->delimiter(',')
        ->expected(3)
        ->type_name("R,G,B")
        ->check(real_in(0, k_max_real, "a colour component of at least 0"));
}

/// A method option whose value is one of a few words.
template <class T>
CLI::Option* add_method_option(CLI::App& app, const MethodOption& option,
                               const ChoiceOption<T>& choice, MethodSettings& own) {
    return add_choice_option(app, option.flag, option.help, choice.choices, choice.field(own));
}

/// The methods that understand the option `flag`, e.g. "zbuffer, scanline".
std::string methods_taking(std::string_view flag) {
    std::vector<std::string_view> names;
    for (const Method& m : methods())
        if (takes_option(m, flag)) names.push_back(m.name);
    return fmt::format("{}", fmt::join(names, ", "));
}

/// Every method option, in a --help group headed by the methods that understand it.
void add_method_options(CLI::App& render, MethodSettings& own) {
    for (const MethodOption* option : method_options())
        std::visit(
            [&](const auto& value) {
                add_method_option(render, *option, value, own)
                    ->group("Options of " + methods_taking(option->flag));
            },
            option->value);
}

/// The options of `method`, e.g. "--spp, --max-depth".
std::string option_list(const Method& method) {
    std::vector<std::string_view> flags;
    for (const MethodOption& option : method.options) flags.push_back(option.flag);
    return fmt::format("{}", fmt::join(flags, ", "));
}

/// The --help footer: every method, and the options it understands beside the common ones.
std::string method_list() {
    std::string text = "Methods (and the options each understands beside the common ones):\n";
    for (const Method& m : methods()) {
        text += fmt::format("  {:<16}{}\n", m.name, m.summary);
        if (!m.options.empty()) text += fmt::format("  {:<16}options: {}\n", "", option_list(m));
    }
    return text;
}

/// A usage error (CLI::ValidationError) when an option's value is one `method` cannot take (a
/// shadow mode it cannot do, no camera ray).
void check_method_values(const Method& method, const MethodSettings& own) {
    if (method.name == "raytrace" && own.max_depth == 0)
        throw CLI::ValidationError(
            "--max-depth 0: raytrace needs at least 1 ray segment (the camera ray)");
    if (own.shadows && takes_option(method, "--shadows") && !does_shadows(method, *own.shadows))
        throw CLI::ValidationError(
            fmt::format("--shadows {}: method {} cannot draw shadows that way (it can: {})",
                        choice_name<std::optional<ShadowMode>>(k_shadow_choices, own.shadows),
                        method.name, shadow_mode_list(method)));
}

/// A usage error (CLI::ValidationError) when the command line gives an option that `method`
/// does not understand, or a value it cannot take.
void check_method_options(const CLI::App& render, const Method& method, const MethodSettings& own) {
    for (const MethodOption* option : method_options()) {
        if (render.count(std::string(option->flag)) == 0 || takes_option(method, option->flag))
            continue;
        throw CLI::ValidationError(fmt::format(
            "{} is not an option of method {} ({})", option->flag, method.name,
            method.options.empty() ? "it takes none" : "it understands: " + option_list(method)));
    }
    check_method_values(method, own);
}

/// Usage errors of the methods asked for: an option or --aov that the one method cannot take;
/// with several methods, an option none of them takes (the others are told it is not theirs)
/// and the same method twice.
void check_render_methods(const CLI::App& render, RenderOptions& o) {
    for (const std::string& name : o.methods) {
        if (std::count(o.methods.begin(), o.methods.end(), name) > 1)
            throw CLI::ValidationError(fmt::format("-m: method {} is named twice", name));
        check_aov_method(*find_method(name), o.aov);
        if (o.wireframe_overlay && find_method(name)->draw)
            throw CLI::ValidationError(fmt::format(
                "--wireframe-overlay draws over a shaded image; {} draws lines already", name));
    }
    if (o.methods.size() == 1) {
        check_method_options(render, *find_method(o.methods.front()), o.own);
        return;
    }
    for (const MethodOption* option : method_options()) {
        if (render.count(std::string(option->flag)) == 0) continue;
        std::vector<std::string_view> ignoring;
        for (const std::string& name : o.methods)
            if (!takes_option(*find_method(name), option->flag)) ignoring.push_back(name);
        if (ignoring.size() == o.methods.size())
            throw CLI::ValidationError(
                fmt::format("{} is not an option of any method asked for "
                            "(it is for: {})",
                            option->flag, methods_taking(option->flag)));
        if (!ignoring.empty())
            o.notes.push_back(fmt::format("{} is not an option of {}, which render without it",
                                          option->flag, fmt::join(ignoring, ", ")));
    }
    for (const std::string& name : o.methods) check_method_values(*find_method(name), o.own);
}

/// Scene, output and method: the first of the render options.
void add_render_inputs(CLI::App& render, RenderOptions& o) {
    render.add_option("scene", o.scene_file,
                      "Scene file (JSON, see docs/scene-format.md), or a model file (.obj, "
                      ".ply, .gltf, .glb) rendered with a camera framed on it and default "
                      "lights; default: the lecture's assignment, a Phong-shaded sphere");
    render.add_option("-o,--output", o.output,
                      "Output image: .png or .ppm (sRGB, 8 or 16 bits, see --bit-depth), .jpg "
                      "(8-bit sRGB, quality 95), .pfm, .exr or .hdr (linear, unclamped), .xlsx (a "
                      "spreadsheet whose cells are the pixels), or .svg (the segments of "
                      "wireframe and hiddenline); default: <scene name>.png (raytrace) or "
                      "<scene name>-<method>.png in the current directory");
    std::vector<std::string> names;
    for (const Method& m : methods()) names.emplace_back(m.name);
    render
        .add_option("-m,--method", o.methods,
                    "Rendering method, or several separated by commas (-m zbuffer,scanline,"
                    "raytrace: one scene load, one image per method, <scene>-<method>.png)")
        ->delimiter(',')
        ->check(CLI::IsMember(names))
        ->default_str("raytrace");
    add_choice_option<Aov>(
        render, "--aov",
        "Buffer to write: color; depth (eye distance), id (1 + primitive index, 0 = background), "
        "normal -- raw values in .pfm/.exr/.hdr, pictures in .png/.jpg/.ppm (depth near white "
        "to far black, ids in false colour, normals as 0.5 + 0.5n); ambient, diffuse, specular: "
        "one term of the shading model alone (Fig 4.29; the three sum to color); overdraw "
        "(zbuffer, depthsort), paint-order (depthsort), spans (scanline), culled (raster "
        "methods): the algorithm at work",
        k_aov_choices, o.aov);
}

/// `--set PATH=VALUE` (repeatable) into `o.overrides`.
void add_set_option(CLI::App& app, RenderOptions& o) {
    app.add_option_function<std::vector<std::string>>(
           "--set",
           [&o](const std::vector<std::string>& args) {
               for (const std::string& a : args) {
                   try {
                       o.overrides.push_back(parse_scene_override(a));
                   } catch (const InputError& e) {
                       throw CLI::ValidationError(e.what());
                   }
               }
           },
           "Override a scene value by its JSON path, as scene errors name it "
           "(--set materials.clay.shininess=5, --set camera.fov_y=30, --set "
           "objects[0].center=[0,1,0]); VALUE is JSON or a bare word (a string); repeatable")
        ->type_name("PATH=VALUE")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

/// The options for rendering a model file (.obj, .ply, .gltf, .glb) as a scene of its own, and
/// for placing the camera of any scene.
void add_model_options(CLI::App& render, RenderOptions& o) {
    render.add_flag("--ground", o.ground,
                    "With a model file: a checkered ground plane just under the model");
    for (auto [flag, field, what] :
         {std::tuple{"--camera-from", &o.camera_from, "Put the camera's eye at X,Y,Z"},
          std::tuple{"--look-at", &o.look_at, "Point the camera at X,Y,Z"}})
        render
            .add_option(flag, *field,
                        std::string(what) + " (overrides the scene's camera or a model's framing)")
            ->delimiter(',')
            ->expected(3)
            ->type_name("X,Y,Z")
            ->check(real_in(-k_max_real, k_max_real));
    render
        .add_option("--crease-angle", o.crease_angle,
                    "Meshes without normals: smooth across edges whose faces meet at less than "
                    "this many degrees, split the normals elsewhere (0: flat faces, Fig 4.5; "
                    "180: smooth everywhere; default: each mesh's \"crease_angle\", else 45)")
        ->check(real_in(0, 180));
}

/// `--exposure`, `--tonemap` and `--bit-depth`: how the colour is developed into the file.
void add_output_development_options(CLI::App& render, RenderOptions& o) {
    render
        .add_option("--exposure", o.exposure,
                    "Multiply the linear colour by 2^EV before writing it, in every format "
                    "(floats included; the render itself is unchanged; not the --aov buffers)")
        ->type_name("EV")
        ->check(real_in(-100, 100))
        ->capture_default_str();
    add_choice_option<ToneMap>(
        render, "--tonemap",
        "How colour above 1 reaches a PNG, JPEG, PPM or spreadsheet (after --exposure; float "
        "files keep radiance): clamp (clip to white, per channel), reinhard (c/(1+c), Reinhard et "
        "al. 2002), aces (Narkowicz's 2015 fit of the ACES filmic curve)",
        k_tone_map_choices, o.tone_map);
    render
        .add_option("--bit-depth", o.bit_depth,
                    "Bits per sample of the sRGB files: 8, or 16 for .png and .ppm")
        ->check(CLI::Validator(
            [](const std::string& bits) {
                return bits == "8" || bits == "16" ? std::string()
                                                   : std::string("expected 8 or 16");
            },
            "8|16"))
        ->capture_default_str();
}

/// `hikari render` and the options every method takes; the methods' own come after them.
CLI::App* add_render_command(CLI::App& app, RenderOptions& o) {
    CLI::App* render = app.add_subcommand("render", "Render a scene file to an image.");
    add_render_inputs(*render, o);
    render->add_option("--width", o.width, "Image width in pixels (overrides the scene)")
        ->check(whole_in(1, 65536));
    render->add_option("--height", o.height, "Image height in pixels (overrides the scene)")
        ->check(whole_in(1, 65536));
    render->add_option("--threads", o.threads, "Worker threads (default: all cores)")
        ->check(whole_in(1, 1024));
    render
        ->add_option("--max-memory", o.max_memory_gib,
                     "Refuse renders whose buffers need more than this many GiB "
                     "(default: half the machine's memory)")
        ->check(real_in(k_least_positive, k_max_real, "a positive number of GiB"));
    render
        ->add_option("--max-input-size", o.max_input_gib,
                     "Refuse input files (scene, mesh, texture, environment map) larger than this "
                     "many GiB (default: 0.25 for a scene, 4 for a mesh, 1 for an image)")
        ->check(real_in(1.0 / (1 << 30), 1 << 20, "a positive number of GiB"));
    render
        ->add_option("--depth-cue", o.depth_cue,
                     "Depth cueing (Fig 4.1b) from eye distance NEAR to FAR: the colour blends "
                     "toward the cue colour (the scene's depth_cue.color, else the background) "
                     "as w·colour + (1−w)·cue, w = clamp((FAR−d)/(FAR−NEAR), 0, 1)")
        ->delimiter(',')
        ->expected(2)
        ->type_name("NEAR,FAR")
        ->check(real_in(0, k_max_real, "a distance of at least 0"));
    render
        ->add_option("--depth-range", o.depth_range,
                     "--aov depth in a picture file: eye distance NEAR is white, FAR black "
                     "(default: the nearest and farthest visible points), so that several "
                     "images share one scale")
        ->delimiter(',')
        ->expected(2)
        ->type_name("NEAR,FAR")
        ->check(real_in(0, k_max_real, "a distance of at least 0"));
    add_output_development_options(*render, o);
    add_set_option(*render, o);
    add_model_options(*render, o);
    render->add_flag("--print-matrices", o.print_matrices,
                     "Print M, P and V of p_s = V P M p_w for the scene's camera, and one vertex "
                     "of each object carried through them (stdout), then render");
    render
        ->add_option("--tessellation", o.tessellation,
                     "Polygons around every sphere's equator when a raster method tessellates "
                     "it (overrides the scene's \"segments\"; default: fine enough for its size "
                     "on screen)")
        ->check(whole_in(k_min_sphere_segments, k_max_sphere_segments));
    render->add_flag("--wireframe-overlay", o.wireframe_overlay,
                     "Draw every triangle's edges over the image: the triangles the raster "
                     "methods fill (spheres and planes tessellated as they tessellate them)");
    render->add_flag("-q,--quiet", o.quiet, "No progress or summary on stderr");
    render->add_flag(
        "--stats", o.stats,
        "Print the load, render and write times, rays (and paths) per second and BVH figures "
        "on stderr");
    add_method_options(*render, o.own);
    render->footer(method_list());
    return render;
}

/// `hikari bench` and its options.
CLI::App* add_bench_command(CLI::App& app, BenchOptions& b) {
    CLI::App* bench = app.add_subcommand(
        "bench", "Run a peer benchmark (bench/SPEC.md) and print one JSON object on stdout.");
    bench
        ->add_option("name", b.bench,
                     "B1 (primary rays, closest hit), B2 (occlusion rays), B4 (rasterized "
                     "1920x1080 Phong frame, as llvmpipe draws it) or B5 (path-traced Cornell "
                     "box, 64 spp, 8 bounces)")
        ->required()
        ->check(CLI::IsMember({"B1", "B2", "B4", "B5"}));
    // No CLI::ExistingFile: a missing or unreadable mesh is an input error (exit 1), as for
    // a render's scene file, reported by the loader.
    bench->add_option("--mesh", b.mesh, "B1, B2, B4: OBJ mesh (positions and faces are read)");
    bench->add_option("--scene", b.scene,
                      "B5: scene file (default: the repository's scenes/bench/cornell.json)");
    bench->add_option("--threads", b.threads, "Threads for build and trace")
        ->check(whole_in(1, 1024))
        ->capture_default_str();
    bench
        ->add_option("--reps", b.repetitions,
                     "Timed repetitions after the warm-up (default: 5; B4: 20 frames after 3; "
                     "B5: 3)")
        ->check(whole_in(1, 1000));
    add_choice_option<std::optional<SimdLevel>>(
        *bench, "--simd", "Traversal kernel: auto (best), portable, avx2, avx512", k_simd_choices,
        b.simd);
    bench->add_flag("--packets", b.packets,
                    "B1 as 4x4 pixel packets (coherent packet traversal); reported as B1p16");
    bench->add_flag("--shadow", b.shadow,
                    "B4 with the 2048x2048 shadow-map pass before every frame");
    bench->add_option("-o,--output", b.output,
                      "B4: write the last frame (PNG, PPM, ...), to compare with llvmpipe's");
    return bench;
}

/// `hikari compare` and its options.
struct CompareOptions {
    std::string a, b;
    std::string output;  // the false-colour difference image; empty: none
    float tolerance = 0.0f;
    bool psnr_only = false;
};

/// Whether `path` is a format that stores 8-bit sRGB values.
bool is_eight_bit_image(const std::filesystem::path& path) {
    const std::optional<ImageFormat> format = image_format_from_extension(path);
    return format == ImageFormat::Png || format == ImageFormat::Jpeg || format == ImageFormat::Ppm;
}

/// `hikari compare A B`: PSNR, the largest difference and the differing pixels of two images,
/// and a false-colour picture of where they differ.
int run_compare(const CompareOptions& o) {
    if (!o.output.empty())
        check_output_path(o.output, std::vector<RenderInput>{{o.a, "the first image"},
                                                             {o.b, "the second image"}});
    const Image a = read_image(o.a), b = read_image(o.b);
    if (a.width != b.width || a.height != b.height)
        throw InputError(fmt::format("{} is {}x{} but {} is {}x{}: only images of one size compare",
                                     o.a, a.width, a.height, o.b, b.width, b.height));
    const ImageDifference d =
        compare_images(a, b, is_eight_bit_image(o.a) && is_eight_bit_image(o.b), o.tolerance);
    if (o.psnr_only) {
        fmt::print("{:.3f}\n", d.psnr_db);
    } else {
        fmt::print("PSNR {:.3f} dB (sRGB values, RGB channels)\n", d.psnr_db);
        fmt::print("max difference {:.4f} ({:.1f}/255) at pixel ({}, {})\n", d.max_difference,
                   255.0 * d.max_difference, d.max_x, d.max_y);
        fmt::print("differing pixels {} of {} ({:.2f} %)\n", d.differing, d.pixels,
                   100.0 * static_cast<double>(d.differing) / static_cast<double>(d.pixels));
    }
    if (!o.output.empty()) {
        write_image(o.output, difference_image(a, b, d.max_difference));
        if (!o.psnr_only)
            fmt::print(
                "wrote {}: black where equal, blue, red, yellow up to the largest "
                "difference\n",
                o.output);
    }
    return 0;
}

/// `hikari compare` and its options.
CLI::App* add_compare_command(CLI::App& app, CompareOptions& c) {
    CLI::App* compare = app.add_subcommand(
        "compare",
        "Compare two images (any format hikari reads): PSNR, largest difference, differing "
        "pixels, and a false-colour difference image.");
    compare->add_option("a", c.a, "First image")->required();
    compare->add_option("b", c.b, "Second image")->required();
    compare->add_option("-o,--output", c.output,
                        "Write where they differ as a false-colour image (black: equal)");
    compare
        ->add_option("--tolerance", c.tolerance,
                     "Pixels differ where a channel's linear values differ by more than this")
        ->check(real_in(0, k_max_real))
        ->capture_default_str();
    compare->add_flag("--psnr", c.psnr_only, "Print the PSNR alone (for scripts)");
    return compare;
}

/// `hikari explain` and its options.
struct ExplainOptions {
    RenderOptions scene;  // the scene file, --set, --width, --height
    std::string method;
    std::optional<int> row;
    std::vector<int> pixel;  // X,Y
};

/// `hikari explain SCENE -m METHOD --row Y | --pixel X,Y`: one step of the algorithm, printed.
int run_explain(const ExplainOptions& e) {
    const Scene scene = load_render_scene(e.scene);
    const RasterSettings raster = e.scene.own.raster;
    if (e.method == "zbuffer") {
        if (e.pixel.empty()) throw InputError("explain -m zbuffer needs --pixel X,Y");
        fmt::print("{}", explain_zbuffer_pixel(scene, raster, e.pixel[0], e.pixel[1]));
    } else if (e.method == "raytrace") {
        if (e.pixel.empty()) throw InputError("explain -m raytrace needs --pixel X,Y");
        WhittedSettings whitted = e.scene.own.whitted;
        if (e.scene.own.max_depth) whitted.max_depth = *e.scene.own.max_depth;
        fmt::print("{}", explain_raytrace_pixel(scene, whitted, e.pixel[0], e.pixel[1]));
    } else if (e.method == "depthsort") {
        fmt::print("{}", explain_depth_sort(scene, raster));
    } else {
        if (!e.row) throw InputError("explain -m scanline needs --row Y");
        fmt::print("{}", explain_scanline_row(scene, raster, *e.row));
    }
    return 0;
}

/// `hikari explain` and its options.
CLI::App* add_explain_command(CLI::App& app, ExplainOptions& e) {
    CLI::App* explain = app.add_subcommand(
        "explain",
        "Print a hidden-surface algorithm's work as it runs on a scene: the Z-buffer's "
        "fragments at a pixel (Alg 4.2), the scanline method's edge table, active edge list "
        "and sample spans at a row (Alg 4.1), or the depth sort's comparisons, reorderings, "
        "splits and painting order (Fig 4.6-4.9), or the ray tracer's ray tree at a pixel "
        "(Alg 4.3).");
    explain->add_option("scene", e.scene.scene_file,
                        "Scene file (default: the lecture's assignment)");
    explain
        ->add_option("-m,--method", e.method,
                     "zbuffer or raytrace (with --pixel), scanline (with --row), or depthsort "
                     "(the whole sort)")
        ->required()
        ->check(CLI::IsMember({"zbuffer", "scanline", "depthsort", "raytrace"}));
    explain->add_option("--row", e.row, "scanline: the row (0 at the top)")
        ->check(whole_in(0, 65535));
    explain
        ->add_option("--pixel", e.pixel, "zbuffer, raytrace: the pixel X,Y (0,0 at the top left)")
        ->delimiter(',')
        ->expected(2)
        ->type_name("X,Y")
        ->check(whole_in(0, 65535));
    explain->add_option("--width", e.scene.width, "Image width in pixels (overrides the scene)")
        ->check(whole_in(1, 65536));
    explain->add_option("--height", e.scene.height, "Image height in pixels (overrides the scene)")
        ->check(whole_in(1, 65536));
    explain
        ->add_option_function<int>(
            "--max-depth", [&e](int d) { e.scene.own.max_depth = d; },
            "raytrace: ray segments per path, the camera ray included (default 5)")
        ->check(whole_in(1, 64));
    add_set_option(*explain, e.scene);
    return explain;
}

/// `hikari gallery` and its options.
CLI::App* add_gallery_command(CLI::App& app, GalleryOptions& g) {
    CLI::App* gallery = app.add_subcommand(
        "gallery",
        "Render the lecture's figures (Fig 4.1 to 4.43) into a directory with an "
        "index.html contact sheet.");
    gallery->add_option("-o,--output", g.dir, "Directory for the images, scenes and index.html")
        ->capture_default_str();
    gallery->add_option("--model", g.model,
                        "Mesh for Fig 4.1 and the others (OBJ; default: the repository's teapot)");
    gallery->add_option("--width", g.width, "Image width in pixels")
        ->check(whole_in(16, 4096))
        ->capture_default_str();
    gallery->add_option("--threads", g.threads, "Render threads (default: all cores)")
        ->check(whole_in(1, 1024));
    gallery
        ->add_option("--lang", g.lang,
                     "Language of the captions: en, or ja (the lecture's own terms)")
        ->check(CLI::IsMember({"en", "ja"}))
        ->capture_default_str();
    gallery
        ->add_option("--only", g.only,
                     "Render only these figures, e.g. --only 4.7,4.9c (labels as captioned)")
        ->delimiter(',');
    return gallery;
}

/// `hikari info FILE`.
CLI::App* add_info_command(CLI::App& app, std::string& file) {
    CLI::App* info = app.add_subcommand(
        "info",
        "Print what a model or scene file holds: triangles, vertices, bounds, materials, "
        "textures, lights, cameras, and the load time.");
    info->add_option("file", file, "Model (.obj, .ply, .gltf, .glb) or scene (.json) file")
        ->required();
    return info;
}

/// This program's own path, to run `hikari render` for each figure.
std::string own_program(const char* argv0) {
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::string(argv0) : self.string();
}

/// Usage errors of --bit-depth, --exposure and --tonemap against the outputs; notes where they
/// do nothing.
void check_output_development(const CLI::App& render, RenderOptions& o) {
    if (std::isnan(o.exposure)) throw CLI::ValidationError("--exposure: EV must be a number");
    const bool developed = render.count("--exposure") > 0 || render.count("--tonemap") > 0;
    if (developed && !is_colour_aov(o.aov))
        o.notes.push_back(fmt::format(
            "--exposure and --tonemap develop colour renders; --aov {} is written as is",
            choice_name<Aov>(k_aov_choices, o.aov)));
    for (const std::string& name : o.methods) {
        const std::string output = output_for(o, name);
        if (!supports_bit_depth(output, o.bit_depth))
            throw CLI::ValidationError(
                fmt::format("--bit-depth {}: {} cannot hold it (16 bits are for .png and .ppm)",
                            o.bit_depth, output));
        if (render.count("--tonemap") > 0 && !is_picture_file(output) && !is_svg_path(output))
            o.notes.push_back(fmt::format(
                "--tonemap is for pictures (.png, .jpg, .ppm, .xlsx); {} keeps linear radiance",
                output));
    }
}

/// Parses the command line (and checks the render's method options); returns the exit status
/// when the program ends there: after --help or --version, or on a usage error.
std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv, const CLI::App& render,
                                      RenderOptions& o, const CLI::App& bench,
                                      const BenchOptions& b) {
    try {
        app.parse(argc, argv);
        if (render.parsed()) check_render_methods(render, o);
        if (bench.parsed() && b.bench != "B5" && b.mesh.empty())
            throw CLI::ValidationError(fmt::format("{} needs --mesh FILE (an OBJ mesh)", b.bench));
        if (!o.depth_cue.empty() && !(o.depth_cue[1] > o.depth_cue[0]))
            throw CLI::ValidationError("--depth-cue: FAR must be greater than NEAR");
        if (!o.depth_range.empty() && !(o.depth_range[1] > o.depth_range[0]))
            throw CLI::ValidationError("--depth-range: FAR must be greater than NEAR");
        if (o.wireframe_overlay && o.aov != Aov::color)
            throw CLI::ValidationError(
                "--wireframe-overlay draws over the colour image (--aov color)");
        if (!o.depth_range.empty() && o.aov != Aov::depth)
            throw CLI::ValidationError("--depth-range is for --aov depth");
        if (render.parsed()) check_output_development(render, o);
        return std::nullopt;
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        fmt::print(stderr, "hikari: error: {}\nRun `hikari --help` for usage.\n", e.what());
        return k_exit_usage_error;
    }
}

/// Runs the parsed subcommand; an error becomes one line on stderr and an exit status.
int run_command(const CLI::App& render, const RenderOptions& o, const CLI::App& bench,
                const BenchOptions& b, const CLI::App& gallery, const GalleryOptions& g,
                const CLI::App& compare, const CompareOptions& c, const CLI::App& explain,
                const ExplainOptions& e, const CLI::App& info, const std::string& info_file,
                const std::string& program) {
    try {
        // The method name was checked by the parser.
        if (render.parsed()) exit_after_render(run_render(o));
        if (bench.parsed()) return run_bench_command(b);
        if (gallery.parsed()) return run_gallery(g, program);
        if (compare.parsed()) return run_compare(c);
        if (explain.parsed()) return run_explain(e);
        if (info.parsed()) {
            fmt::print("{}", info_report(info_file));
            return 0;
        }
    } catch (const UsageError& e) {
        fmt::print(stderr, "hikari: error: {}\n", e.what());
        return k_exit_usage_error;
    } catch (const std::exception& e) {
        // After SIGINT / SIGTERM, whatever unwound the stage (Interrupted, or a read cut short
        // by the signal) is the interruption, not an error of the input.
        if (cancel_requested() || dynamic_cast<const Interrupted*>(&e)) {
            report_interrupted();
            return interrupted_status();
        }
        const bool out_of_memory = dynamic_cast<const std::bad_alloc*>(&e) != nullptr;
        fmt::print(stderr, "hikari: error: {}\n", out_of_memory ? "out of memory" : e.what());
        return k_exit_input_error;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    install_signal_handlers();
    keep_freed_memory();
    CLI::App app{"hikari: every classic rendering method of the lecture, in one renderer.",
                 "hikari"};
    app.set_version_flag("--version", fmt::format("hikari {}", k_version));
    app.require_subcommand(1);
    app.footer("Run `hikari render --help` for the render options.");
    RenderOptions o;
    BenchOptions b;
    const CLI::App* render = add_render_command(app, o);
    const CLI::App* bench = add_bench_command(app, b);
    GalleryOptions g;
    const CLI::App* gallery = add_gallery_command(app, g);
    CompareOptions c;
    const CLI::App* compare = add_compare_command(app, c);
    ExplainOptions e;
    const CLI::App* explain = add_explain_command(app, e);
    std::string info_file;
    const CLI::App* info = add_info_command(app, info_file);
    if (const std::optional<int> status =
            parse_command_line(app, argc, argv, *render, o, *bench, b))
        return *status;
    return run_command(*render, o, *bench, b, *gallery, g, *compare, c, *explain, e, *info,
                       info_file, own_program(argv[0]));
}
