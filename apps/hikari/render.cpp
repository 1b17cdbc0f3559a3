#include "render.h"

#include <chrono>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <tbb/global_control.h>

#include "cli_options.h"
#include "console.h"
#include "hikari/core/error.h"
#include "hikari/explain/algorithm_aovs.h"
#include "hikari/explain/explain.h"
#include "hikari/io/images/image_write.h"
#include "hikari/io/images/svg_write.h"
#include "hikari/methods/registry.h"
#include "hikari/raster/lines/wireframe.h"
#include "load_scene.h"
#include "output_paths.h"
#include "progress.h"
#include "render_output.h"
#include "render_report.h"
#include "signals.h"

namespace hikari::cli {

namespace {

using Clock = std::chrono::steady_clock;

/// `--wireframe-overlay`'s line colour: near black, a figure's ink.
constexpr Vec3 k_overlay_colour{0.02f, 0.02f, 0.02f};

/// A method and the file its render goes to.
struct Run {
    const Method* method;
    std::string output;
};

/// Seconds since `start`.
double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

/// --threads, for as long as it lives (0: all cores).
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

/// Refuses, before any work is done, an SVG output that the method or --aov cannot give: a
/// command-line mistake (exit 2), like any other -o mistake.
void check_svg_output(const std::string& output, const Method& method, Aov aov) {
    if (!is_svg_path(output)) return;
    if (!method.draw)
        throw UsageError(
            fmt::format("{}: SVG output is for the line methods ({}); method {} draws no lines",
                        output, drawing_methods(), method.name));
    if (aov != Aov::color)
        throw UsageError(
            fmt::format("{}: SVG output holds the lines' colours; --aov {} needs an "
                        "image format",
                        output, aov_name(aov)));
}

/// Every method asked for with its output, each output checked.
std::vector<Run> planned_runs(const RenderOptions& o) {
    std::vector<Run> runs;
    const std::vector<RenderInput> inputs = render_inputs(o.scene_file);
    for (const std::string& name : o.methods) {
        const Method& method = *find_method(name);  // checked by the parser
        const std::string output = output_for(o, name);
        check_output_path(output, inputs);
        check_svg_output(output, method, o.aov);
        runs.push_back({&method, output});
    }
    return runs;
}

/// The line method's drawing written as SVG (`-o drawing.svg`).
void run_drawing(const RenderOptions& o, const Method& method, const std::string& output) {
    const Scene scene = load_render_scene(o);
    const ThreadLimit thread_limit(o.threads);
    const auto start = Clock::now();
    const LineDrawing drawing = draw_scene(method, scene, o.own);
    const double seconds = seconds_since(start);
    if (render_control().cancel.load()) throw Interrupted();
    write_svg(output, drawing);
    if (!o.quiet)
        print_err("hikari: wrote {} ({}x{}, {}, {} segments, {:.3f} s)\n", output, drawing.width,
                  drawing.height, method.name, drawing.segments.size(), seconds);
}

/// An algorithm AOV (`--aov overdraw | paint-order | spans | culled`) of the method at work.
void render_algorithm_aov(const RenderOptions& o, const Scene& scene, const Method& method,
                          const std::string& output) {
    const bool raw = !is_picture_file(output);
    const auto start = Clock::now();
    const AlgorithmAov a = algorithm_aov(scene, method, o.aov, o.own, raw);
    if (render_control().cancel.load()) throw Interrupted();
    write_image(output, a.image, ImageWriteSettings{o.bit_depth});
    if (!o.quiet)
        print_err("hikari: wrote {} ({}x{}, {}, {:.3f} s)\nhikari: {}\n", output, a.image.width,
                  a.image.height, method.name, seconds_since(start), a.summary);
}

/// The render step: `method` on the loaded scene into the film `output` needs, with the wireframe
/// overlaid if asked; progress on stderr, figures into `stats`.
Framebuffer render_image(const RenderOptions& o, const Scene& scene, const Method& method,
                         const std::string& output, RenderStats& stats) {
    MethodSettings own = o.own;
    if (own.path.progressive_seconds > 0.0f && o.aov == Aov::color)
        own.path.snapshot = [&output, &o](const Image& mean, int) {
            write_progressive_snapshot(output, mean, o);
        };
    RenderControl& control = render_control();
    control.work_done = 0;
    control.work_total = 0;
    RenderSettings settings;
    settings.control = &control;
    settings.stats = &stats;
    settings.aov_buffers = !is_colour_aov(o.aov) || o.wireframe_overlay;
    const ThreadLimit thread_limit(o.threads);
    Framebuffer fb;
    {
        ProgressReporter progress(!o.quiet, "rendering",
                                  double(scene.camera.width) * scene.camera.height);
        fb = render_scene(method, scene,
                          o.wireframe_overlay ? Film(scene.camera, FilmFormat::linear)
                                              : output_film(scene.camera, output, o),
                          settings, own);
    }
    if (o.wireframe_overlay && !control.cancel.load()) {
        LineSettings lines;
        lines.triangle_edges = true;
        lines.cull_back_faces = own.raster.cull_back_faces;
        overlay_wireframe(scene, lines, k_overlay_colour, fb.depth, fb.film.linear());
    }
    return fb;
}

/// What follows a written render on stderr: the summary, NaN samples left out, --stats.
void report_render(const RenderOptions& o, const Run& run, const Scene& scene, int width,
                   int height, const PhaseTimes& times, const RenderStats& stats) {
    if (!o.quiet) print_summary(run.output, width, height, *run.method, scene, times, stats);
    if (const uint64_t bad = stats.bad_samples.load(); bad > 0)
        print_err(
            "hikari: warning: {} samples were NaN or infinite and were left out of the image "
            "(their pixels average the other samples as if these were black)\n",
            bad);
    if (o.stats) print_stats(times, stats, *run.method);
}

/// One method's render of the loaded scene into its output. `load_seconds`: the time spent
/// loading, for --stats.
void render_with(const RenderOptions& o, const Scene& scene, const Run& run, double load_seconds) {
    if (is_algorithm_aov(o.aov)) return render_algorithm_aov(o, scene, *run.method, run.output);
    if (run.method->warnings)
        for (const std::string& w : run.method->warnings(scene))
            print_err("hikari: warning: {}\n", w);
    RenderStats stats;
    PhaseTimes times;
    times.load = load_seconds;
    const auto start = Clock::now();
    Framebuffer fb = render_image(o, scene, *run.method, run.output, stats);
    times.render = seconds_since(start);
    const auto rendered = Clock::now();
    const int width = fb.width(), height = fb.height();
    write_output(run.output, std::move(fb), o);
    times.write = seconds_since(rendered);
    report_render(o, run, scene, width, height, times, stats);
}

}  // namespace

int run_render(const RenderOptions& o) {
    const auto load_start = Clock::now();
    const std::vector<Run> runs = planned_runs(o);
    if (is_svg_path(runs.front().output)) {
        for (const Run& run : runs) run_drawing(o, *run.method, run.output);
        return 0;
    }
    for (const std::string& note : o.notes) print_err("hikari: warning: {}\n", note);
    const Scene scene = load_render_scene(o);
    for (const Run& run : runs) check_spreadsheet_size(run.output, scene.camera);
    if (o.print_matrices) print_out("{}", explain_matrices(scene, o.own.raster));
    const double load_seconds = seconds_since(load_start);
    for (const Run& run : runs) render_with(o, scene, run, load_seconds);
    return 0;
}

}  // namespace hikari::cli
