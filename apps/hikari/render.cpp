#include "render.h"

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "cli_options.h"
#include "console.h"
#include "hikari/core/error.h"
#include "hikari/explain/explain.h"
#include "hikari/frame/tile_share.h"
#include "hikari/io/images/image_write.h"
#include "hikari/io/images/svg_write.h"
#include "hikari/methods/registry.h"
#include "load_scene.h"
#include "mpi_frames.h"
#include "output_paths.h"
#include "progress.h"
#include "render_frames.h"
#include "render_output.h"
#include "render_report.h"
#include "signals.h"

namespace hikari::cli {

namespace {

using Clock = std::chrono::steady_clock;

/// A method and the file its render goes to.
struct Run {
    const Method* method;
    std::string output;
};

/// Seconds since `start`.
double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

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
void run_drawing(const RenderOptions& o, Session& session, const Method& method,
                 const std::string& output) {
    RenderRequest request = render_request(o);
    request.method = method.name;
    const auto start = Clock::now();
    const LineDrawing drawing = session.draw(request);
    const double seconds = seconds_since(start);
    if (render_control().cancel.load()) throw Interrupted();
    write_svg(output, drawing);
    if (!o.quiet)
        print_err("hikari: wrote {} ({}x{}, {}, {} segments, {:.3f} s)\n", output, drawing.width,
                  drawing.height, method.name, drawing.segments.size(), seconds);
}

/// The request for `run`: the options' own, the film its output needs, progress mirrored into
/// the counters the progress line reads, and a progressive path render's snapshots.
RenderRequest run_request(const RenderOptions& o, const Session& session, const Run& run) {
    RenderRequest request = render_request(o);
    request.method = run.method->name;
    request.film = output_film(session.camera_for(request), run.output, o).format();
    request.algorithm_counts = !is_picture_file(run.output);
    if (request.options.path.progressive_seconds > 0.0f && o.aov == Aov::color)
        request.options.path.snapshot = [output = run.output, &o](const Image& mean, int) {
            write_progressive_snapshot(output, mean, o);
        };
    RenderControl& control = render_control();
    control.work_done = 0;
    control.work_total = 0;
    request.progress = [&control](const RenderProgress& p) {
        constexpr double k_units = 1e9;
        control.work_total = static_cast<uint64_t>(k_units);
        control.work_done = static_cast<uint64_t>(p.fraction * k_units);
    };
    return request;
}

/// An algorithm AOV (`--aov overdraw | paint-order | spans | culled`) of the method at work.
void write_algorithm_aov(const RenderOptions& o, const Run& run, const RenderResult& result) {
    write_image(run.output, *result.algorithm_picture, image_write_settings(o));
    if (!o.quiet)
        print_err("hikari: wrote {} ({}x{}, {}, {:.3f} s)\nhikari: {}\n", run.output,
                  result.algorithm_picture->width, result.algorithm_picture->height,
                  run.method->name, result.seconds, result.algorithm_summary);
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

/// One method's render of the session's scene into its output. `load_seconds`: the time spent
/// loading, for --stats (0 after the first render: the session loaded once). Under mpirun, a
/// method that shares tiles renders on every rank and rank 0 writes the gathered image; the
/// others render on rank 0 alone.
void render_with(const RenderOptions& o, Session& session, const Run& run, double load_seconds,
                 const MpiJob& job) {
    RenderRequest request = run_request(o, session, run);
    const bool shared = job.size() > 1 && run.method->shares_tiles && !is_algorithm_aov(o.aov);
    if (job.rank() != 0 && !shared) return;
    const TileShare share{job.rank(), job.size(), [&job](Framebuffer& fb) { job.gather_tiles(fb); },
                          [&job](std::span<int64_t> sums) { job.sum_over_ranks(sums); }};
    if (shared) request.tile_share = &share;
    RenderResult result;
    {
        const Camera camera = session.camera_for(request);
        ProgressReporter progress(!o.quiet && !is_algorithm_aov(o.aov), "rendering",
                                  double(camera.width) * camera.height);
        result = session.render(request);
    }
    if (shared) {
        RenderStats& stats = *result.stats;
        for (std::atomic<uint64_t>* count :
             {&stats.rays_traced, &stats.paths_traced, &stats.bad_samples})
            *count = static_cast<uint64_t>(job.total(static_cast<long long>(count->load())));
        if (job.rank() != 0) return;
    }
    if (result.algorithm_picture) return write_algorithm_aov(o, run, result);
    for (const std::string& w : result.warnings) print_err("hikari: warning: {}\n", w);
    PhaseTimes times;
    times.load = load_seconds;
    times.render = result.seconds;
    const auto rendered = Clock::now();
    const int width = result.framebuffer.width(), height = result.framebuffer.height();
    const std::unique_ptr<RenderStats> stats = std::move(result.stats);
    write_output(run.output, std::move(result), o, session.scene());
    times.write = seconds_since(rendered);
    report_render(o, run, session.scene(), width, height, times, *stats);
}

/// Under mpirun, one image is shared by tiles: refuses what would make the ranks' tiles differ.
void check_shared_still(const RenderOptions& o) {
    const PathSettings& path = o.own.path;
    if (path.time_limit_seconds > 0.0f || path.progressive_seconds > 0.0f)
        throw UsageError(
            "under mpirun, the ranks share one image's tiles, and --time-limit or --progressive "
            "would give each rank's tiles another number of samples: give --spp instead");
}

/// The stills of `runs` (one per method); under mpirun every rank calls it, and only rank 0
/// speaks and writes.
int render_still(const RenderOptions& o, const std::vector<Run>& runs, const MpiJob& job) {
    const bool writer = job.rank() == 0;
    const auto load_start = Clock::now();
    if (writer && !is_svg_path(runs.front().output))
        for (const std::string& note : o.notes) print_err("hikari: warning: {}\n", note);
    RenderOptions rank_options = o;
    rank_options.quiet = o.quiet || !writer;
    const std::unique_ptr<Session> session = load_render_session(rank_options);
    const Camera camera = session->camera_for(render_request(o));
    check_image_memory(camera);
    if (is_svg_path(runs.front().output)) {
        if (writer)
            for (const Run& run : runs) run_drawing(o, *session, *run.method, run.output);
        return 0;
    }
    for (const Run& run : runs) check_spreadsheet_size(run.output, camera);
    if (o.formulas) {
        if (!writer) return 0;
        write_formula_workbook(runs.front().output, session->scene_as_rendered(render_request(o)),
                               o);
        if (!o.quiet) print_err("hikari: wrote {} (formulas)\n", runs.front().output);
        return 0;
    }
    if (o.print_matrices && writer)
        print_out("{}",
                  explain_matrices(session->scene_as_rendered(render_request(o)), o.own.raster));
    double load_seconds = seconds_since(load_start);
    for (const Run& run : runs) {
        render_with(rank_options, *session, run, load_seconds, job);
        load_seconds = 0;
    }
    return 0;
}

}  // namespace

int run_render(const RenderOptions& o) {
    if (is_frame_render(o)) return run_frame_render(o);
    // The command line's mistakes before MPI starts: under mpirun each rank says why and exits
    // with status 2, with no MPI_Abort report around it.
    const std::vector<Run> runs = planned_runs(o);
    if (launched_among_ranks()) check_shared_still(o);
    const MpiJob job;
    if (job.size() < 2) return render_still(o, runs, job);
    // A rank that stops must stop the others: they would wait for its tiles forever.
    try {
        return render_still(o, runs, job);
    } catch (const std::exception& e) {
        job.abort(e);
    }
}

}  // namespace hikari::cli
