// run_frame_render (render_frames.h): the frames rendered on one session, written as numbered
// files or piped into a video, with one progress line.

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "cli_options.h"
#include "console.h"
#include "hikari/core/error.h"
#include "hikari/core/srgb8_encoder.h"
#include "hikari/frame/side_by_side.h"
#include "hikari/io/files/frame_pattern.h"
#include "hikari/io/images/image_write.h"
#include "hikari/io/images/svg_write.h"
#include "hikari/io/video/video_pipe.h"
#include "hikari/scene/camera_orbit.h"
#include "hikari/session/frame_selection.h"
#include "hikari/session/scene_animation.h"
#include "load_scene.h"
#include "mpi_frames.h"
#include "output_paths.h"
#include "render_frames.h"
#include "render_output.h"
#include "signals.h"

namespace hikari::cli {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// A method and where its frames go: numbered files, or one video. With --side-by-side, every
/// method, their pictures of a frame side by side in one output.
struct FrameRun {
    std::vector<const Method*> methods;
    std::string output;
    std::optional<FramePattern> pattern;  ///< numbered files; nullopt: a video

    /// The method names, as the summary line gives them ("zbuffer" or "wireframe,zbuffer").
    std::string names() const {
        std::string out;
        for (const Method* m : methods) out += (out.empty() ? "" : ",") + std::string(m->name);
        return out;
    }
};

/// The frames this process renders: --frames (default: all of them) of --shard, as
/// check_frame_options accepted them.
std::vector<int> planned_frames(const FrameOptions& f) {
    std::string why;
    FrameRange range{0, frame_count(f) - 1};
    if (!f.range.empty()) range = *parse_frame_range(f.range, why);
    FrameShard shard;
    if (!f.shard.empty()) shard = *parse_frame_shard(f.shard, why);
    return shard_frames(range, shard);
}

/// A video's directory: it must exist and be writable; and ffmpeg must be there, before any
/// frame is rendered.
void check_video_output(const fs::path& video, std::span<const RenderInput> inputs) {
    std::error_code ec;
    const fs::path dir = video.has_parent_path() ? video.parent_path() : ".";
    if (!fs::is_directory(dir, ec) || ::access(dir.c_str(), W_OK) != 0)
        throw UsageError(
            fmt::format("{}: cannot write: the directory {} {}", video.string(), dir.string(),
                        fs::is_directory(dir, ec) ? "is not writable" : "does not exist"));
    for (const RenderInput& input : inputs)
        if (fs::equivalent(video, input.file, ec))
            throw UsageError(fmt::format("{}: refusing to overwrite {} with the video",
                                         video.string(), input.role));
    if (!find_ffmpeg()) throw UsageError(missing_ffmpeg_message(video));
}

/// The methods and their outputs: one run per method, or one of them all with --side-by-side.
std::vector<FrameRun> method_runs(const RenderOptions& o) {
    std::vector<FrameRun> runs;
    for (const std::string& name : o.methods) {
        if (o.frames.side_by_side && !runs.empty())
            runs.front().methods.push_back(find_method(name));
        else
            runs.push_back({{find_method(name)},
                            o.frames.side_by_side ? o.output : output_for(o, name),
                            std::nullopt});
    }
    return runs;
}

/// Every method with its output, each frame's file checked before any work is done.
std::vector<FrameRun> planned_runs(const RenderOptions& o, const std::vector<int>& frames) {
    const std::vector<RenderInput> inputs = render_inputs(o.scene_file);
    std::vector<FrameRun> runs = method_runs(o);
    for (FrameRun& run : runs) {
        std::string why;
        if (is_video_path(run.output))
            check_video_output(run.output, inputs);
        else
            run.pattern = parse_frame_pattern(run.output, why);  // checked by the parser
        if (run.pattern)
            for (const int frame : frames) check_output_path(run.pattern->file_name(frame), inputs);
    }
    return runs;
}

/// The progress line: the frame at work, the frames done of this process's and the time left.
/// On a terminal one line, rewritten; otherwise (a batch job's log) one line per frame.
class FrameProgress {
  public:
    FrameProgress(bool enabled, size_t total)
        : m_enabled(enabled), m_terminal(::isatty(STDERR_FILENO) == 1), m_total(total) {}
    ~FrameProgress() {
        if (m_enabled && m_terminal && m_shown) print_err("\n");
    }

    /// Frame `frame` starts (after `skipped` frames were found done).
    void starting(int frame) {
        if (!m_enabled) return;
        std::string eta = "ETA --";
        if (m_rendered > 0) {
            const double per_frame =
                std::chrono::duration<double>(Clock::now() - m_start).count() / m_rendered;
            const auto left = static_cast<long>(per_frame * double(m_total - m_done) + 0.5);
            eta = fmt::format("ETA {}:{:02}:{:02}", left / 3600, left / 60 % 60, left % 60);
        }
        print_err("{}hikari: frame {}, {}/{} done, {}{}", m_terminal ? "\r\033[K" : "", frame,
                  m_done, m_total, eta, m_terminal ? "" : "\n");
        m_shown = true;
    }
    void skipped() { ++m_done; }
    void rendered() {
        ++m_done;
        ++m_rendered;
    }
    size_t rendered_count() const { return m_rendered; }

  private:
    bool m_enabled, m_terminal, m_shown = false;
    size_t m_total, m_done = 0, m_rendered = 0;
    Clock::time_point m_start = Clock::now();
};

/// Puts each frame on the session: the turntable's camera, or the scene of the animation's frame.
class FrameStage {
  public:
    FrameStage(const RenderOptions& o, Session& session)
        : m_session(session), m_request(render_request(o)), m_turntable(o.frames.turntable) {
        if (m_turntable == 0) {
            m_animation = SceneAnimation::of(scene_source(o));
            if (!m_animation)
                throw InputError(
                    fmt::format("{}: the scene has no \"animation\" block any more", o.scene_file));
        }
        m_base = session.camera_for(m_request);
    }

    /// The camera the frames start from (their image size).
    const Camera& base() const { return m_base; }
    /// Frame `frame`'s camera; an animation's frame scene put on the session.
    Camera camera(int frame) {
        if (!m_animation) return turntable_camera(m_base, frame, m_turntable);
        m_animation->show(m_session, frame);
        return m_session.camera_for(m_request);
    }

  private:
    Session& m_session;
    RenderRequest m_request;
    int m_turntable;
    std::optional<SceneAnimation> m_animation;
    Camera m_base;
};

/// The request for one frame by `method`: the options' own with the frame's camera, the film its
/// output `file` needs (a video frame, a side-by-side panel: "frame.png", what an 8-bit PNG
/// holds).
RenderRequest frame_request(const RenderOptions& o, const Method& method, const std::string& file,
                            const Camera& camera) {
    RenderRequest request = render_request(o);
    request.method = method.name;
    request.camera = camera;
    request.width = camera.width;
    request.height = camera.height;
    request.film = output_film(camera, file, o).format();
    request.algorithm_counts = !is_picture_file(file);
    return request;
}

/// A finished frame as the 8-bit sRGB picture an 8-bit PNG of it holds.
Srgb8Image frame_picture(RenderResult&& result, const RenderOptions& o, const Scene& scene) {
    if (render_control().cancel.load()) throw Interrupted();
    DevelopedImage image = develop(std::move(result), development(o, true), scene);
    if (auto* srgb8 = std::get_if<Srgb8Image>(&image)) return std::move(*srgb8);
    return encode_srgb8(std::get<Image>(image));
}

/// The picture of one frame of `run` at `camera`, as an 8-bit PNG holds it: its method's, or
/// with --side-by-side every method's, left to right under their names (frame/side_by_side.h).
Srgb8Image run_picture(const RenderOptions& o, Session& session, const FrameRun& run,
                       const Camera& camera, bool first) {
    std::vector<Srgb8Image> panels;
    std::vector<std::string> labels;
    for (const Method* method : run.methods) {
        RenderResult result = session.render(frame_request(o, *method, "frame.png", camera));
        if (first)
            for (const std::string& w : result.warnings) print_err("hikari: warning: {}\n", w);
        panels.push_back(frame_picture(std::move(result), o, session.scene()));
        labels.emplace_back(method->name);
    }
    if (!o.frames.side_by_side) return std::move(panels.front());
    return side_by_side(panels, labels);
}

/// One frame rendered into `file`, as `hikari render` with that camera writes it.
void render_frame_file(const RenderOptions& o, Session& session, const FrameRun& run,
                       const Camera& camera, const std::string& file, bool first) {
    if (o.frames.side_by_side)
        return write_image(file, run_picture(o, session, run, camera, first));
    const RenderRequest request = frame_request(o, *run.methods.front(), run.output, camera);
    if (is_svg_path(file)) return write_svg(file, session.draw(request));
    RenderResult result = session.render(request);
    if (first)
        for (const std::string& w : result.warnings) print_err("hikari: warning: {}\n", w);
    write_output(file, std::move(result), o, session.scene());
}

/// Whether a frame's file is there whole: files are written atomically (io/files/atomic_file.h),
/// so one under the frame's own name was finished; a stopped write leaves only a temporary.
bool frame_is_done(const std::string& file) {
    std::error_code ec;
    return fs::is_regular_file(file, ec) && fs::file_size(file, ec) > 0 && !ec;
}

/// What a run of frames did, for the summary.
struct FrameTally {
    size_t rendered = 0, skipped = 0;
};

/// The frames of `run` as numbered files, shared among the MPI job's ranks; those already there
/// skipped unless --overwrite. The tally is this rank's.
FrameTally render_frame_files(const RenderOptions& o, Session& session, const FrameRun& run,
                              FrameStage& stage, const std::vector<int>& frames,
                              const MpiJob& job) {
    FrameProgress progress(!o.quiet && job.rank() == 0, frames.size());
    FrameTally tally;
    job.share(frames, [&](int frame) {
        const std::string file = run.pattern->file_name(frame);
        if (!o.frames.overwrite && frame_is_done(file)) {
            progress.skipped();
            ++tally.skipped;
            return;
        }
        progress.starting(frame);
        const Camera camera = stage.camera(frame);
        render_frame_file(o, session, run, camera, file, tally.rendered == 0 && job.rank() == 0);
        progress.rendered();
        ++tally.rendered;
    });
    return tally;
}

/// The size of `run`'s frames: the camera's, or with --side-by-side the labelled panels'.
PictureSize frame_size(const RenderOptions& o, const FrameRun& run, const Camera& camera) {
    if (!o.frames.side_by_side) return {camera.width, camera.height};
    std::vector<std::string> labels;
    for (const Method* m : run.methods) labels.emplace_back(m->name);
    return side_by_side_size({camera.width, camera.height}, labels);
}

/// H.264 in yuv420p keeps colour at half resolution in both directions: an even size only.
void check_video_size(const FrameRun& run, PictureSize size) {
    const std::string ext = fs::path(run.output).extension().string();
    if (ext == ".mp4" && (size.width % 2 != 0 || size.height % 2 != 0))
        throw UsageError(fmt::format(
            "{}: H.264 video (yuv420p) needs an even width and height; the frames are {}x{} "
            "(set --width and --height)",
            run.output, size.width, size.height));
}

/// The frames of `run` piped into its video, in order, none on the disk.
FrameTally render_video(const RenderOptions& o, Session& session, const FrameRun& run,
                        FrameStage& stage, const std::vector<int>& frames) {
    const PictureSize size = frame_size(o, run, stage.base());
    VideoPipe video(run.output, VideoSettings{size.width, size.height, o.frames.fps});
    FrameProgress progress(!o.quiet, frames.size());
    FrameTally tally;
    for (const int frame : frames) {
        progress.starting(frame);
        const Camera camera = stage.camera(frame);
        const Srgb8Image picture = run_picture(o, session, run, camera, tally.rendered == 0);
        video.write_frame(picture.bytes);
        progress.rendered();
        ++tally.rendered;
    }
    video.finish();
    return tally;
}

/// `o` without its messages (-q): the MPI ranks after the first, which would repeat them.
RenderOptions quiet(RenderOptions o) {
    o.quiet = true;
    return o;
}

/// The line after a run's frames: how many, where, how fast.
void report_frames(const RenderOptions& o, const FrameRun& run, const FrameTally& tally,
                   double seconds) {
    if (o.quiet) return;
    const std::string skipped =
        tally.skipped > 0
            ? fmt::format(", {} already there (--overwrite renders them)", tally.skipped)
            : "";
    print_err("hikari: wrote {} frame{} to {} ({}{}, {:.3f} s, {:.2f} frames/s)\n", tally.rendered,
              tally.rendered == 1 ? "" : "s", run.output, run.names(), skipped, seconds,
              seconds > 0 ? double(tally.rendered) / seconds : 0.0);
}

}  // namespace

int run_frame_render(const RenderOptions& o) {
    if (frame_count(o.frames) == 0) {
        load_render_session(o);  // the checks could not read the scene: its load says why
        throw InputError(fmt::format("{}: the scene has no \"animation\" block", o.scene_file));
    }
    const std::vector<int> frames = planned_frames(o.frames);
    const std::vector<FrameRun> runs = planned_runs(o, frames);
    const MpiJob job;
    for (const FrameRun& run : runs)
        if (!run.pattern && job.size() > 1)
            throw UsageError(
                fmt::format("{}: a video takes every frame in one process; under "
                            "mpirun, write numbered images (-o frame_%04d.png)",
                            run.output));
    for (const std::string& note : o.notes) print_err("hikari: warning: {}\n", note);
    const std::unique_ptr<Session> session = load_render_session(job.rank() == 0 ? o : quiet(o));
    FrameStage stage(o, *session);
    check_image_memory(stage.base());
    for (const FrameRun& run : runs)
        if (!run.pattern) check_video_size(run, frame_size(o, run, stage.base()));
    for (const FrameRun& run : runs) {
        const auto start = Clock::now();
        FrameTally tally = run.pattern ? render_frame_files(o, *session, run, stage, frames, job)
                                       : render_video(o, *session, run, stage, frames);
        tally.rendered = static_cast<size_t>(job.total(static_cast<long long>(tally.rendered)));
        tally.skipped = static_cast<size_t>(job.total(static_cast<long long>(tally.skipped)));
        if (job.rank() == 0)
            report_frames(o, run, tally,
                          std::chrono::duration<double>(Clock::now() - start).count());
    }
    return 0;
}

}  // namespace hikari::cli
