#include "render_frames.h"

#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli_options.h"
#include "hikari/io/files/frame_pattern.h"
#include "hikari/io/images/svg_write.h"
#include "hikari/io/video/video_pipe.h"
#include "hikari/session/frame_selection.h"
#include "hikari/session/scene_animation.h"
#include "load_scene.h"
#include "output_paths.h"

namespace hikari::cli {

namespace {

/// --frames: a range A-B within the turntable's or the animation's frames.
void check_frame_range(const FrameOptions& f) {
    std::string why;
    const std::optional<FrameRange> range = parse_frame_range(f.range, why);
    if (!range) throw CLI::ValidationError(fmt::format("--frames {}: {}", f.range, why));
    if (range->last >= frame_count(f))
        throw CLI::ValidationError(
            fmt::format("--frames {}: the {} has frames 0 to {}", f.range,
                        f.turntable > 0 ? fmt::format("turntable (--turntable {})", f.turntable)
                                        : "scene's animation",
                        frame_count(f) - 1));
}

/// Whether the options ask for frames of whatever animation the scene holds: a frame option,
/// a video, or an output with a frame number.
bool asks_for_frames(const CLI::App& render, const RenderOptions& o) {
    for (const char* flag : {"--frames", "--shard", "--overwrite", "--fps", "--side-by-side"})
        if (render.count(flag) > 0) return true;
    if (o.output.empty()) return false;
    std::string why;
    for (const std::string& name : o.methods)
        if (is_video_path(output_for(o, name)) || parse_frame_pattern(output_for(o, name), why))
            return true;
    return false;
}

/// What the scene offers as frames.
enum class SceneFrames { none, animation, unreadable };

/// The scene's "animation" block, its frame count (and rate, without --fps) kept in `o`. A
/// scene that cannot be read is left to the load, which says why.
SceneFrames read_animation(const CLI::App& render, RenderOptions& o) {
    try {
        const std::optional<SceneAnimation> animation = SceneAnimation::of(scene_source(o));
        if (!animation) return SceneFrames::none;
        o.frames.animation_frames = animation->frame_count();
        if (render.count("--fps") == 0) o.frames.fps = animation->fps();
        return SceneFrames::animation;
    } catch (const std::exception&) {
        return SceneFrames::unreadable;
    }
}

/// --side-by-side: -o as given, a video or 8-bit pictures with a frame number (the labels are
/// display values, drawn into the picture).
void check_side_by_side_output(const RenderOptions& o) {
    if (is_video_path(o.output)) return;
    std::string why;
    if (!is_picture_file(o.output) || is_svg_path(o.output) || o.bit_depth != 8)
        throw CLI::ValidationError(fmt::format(
            "-o {}: --side-by-side draws the methods' labels into 8-bit pictures: write a video "
            "(.mp4, .webm, .gif) or numbered .png, .jpg or .ppm frames",
            o.output));
    if (!parse_frame_pattern(o.output, why))
        throw CLI::ValidationError(
            fmt::format("-o {}: a frame output needs a frame number: {}", o.output, why));
}

/// -o of every method: a video, or a file name with a frame number in it.
void check_frame_outputs(const RenderOptions& o) {
    if (o.output.empty())
        throw CLI::ValidationError(
            "name the frames' files with -o and a frame number (-o out/frame_%04d.png), or a "
            "video (-o turntable.mp4, .webm or .gif)");
    if (o.frames.side_by_side) return check_side_by_side_output(o);
    for (const std::string& name : o.methods) {
        const std::string output = output_for(o, name);
        std::string why;
        if (is_video_path(output)) {
            if (!o.frames.shard.empty())
                throw CLI::ValidationError(
                    fmt::format("{}: a video takes every frame in one process; with --shard, write "
                                "numbered images (-o frame_%04d.png) and encode them afterwards",
                                output));
        } else if (is_svg_path(output) && !find_method(name)->draw) {
            throw CLI::ValidationError(
                fmt::format("{}: SVG output is for the line methods ({}); method {} draws no lines",
                            output, drawing_methods(), name));
        } else if (!parse_frame_pattern(output, why)) {
            throw CLI::ValidationError(
                fmt::format("-o {}: a frame output needs a frame number: {}", output, why));
        }
    }
}

}  // namespace

void add_frame_options(CLI::App& render, FrameOptions& f) {
    render
        .add_option("--turntable", f.turntable,
                    "Render N frames of the camera orbiting the point it looks at (the scene's "
                    "camera, or a model's framing), about its up axis, keeping its elevation and "
                    "distance; frame k turned by k/N of a turn. -o names the frames "
                    "(out/frame_%04d.png) or a video (.mp4, .webm, .gif; needs ffmpeg)")
        ->check(whole_in(1, 1000000));
    render
        .add_option("--frames", f.range,
                    "Render frames A to B (numbered from 0) of the --turntable, or of the scene's "
                    "\"animation\" block (without --frames: all of them, with -o naming the "
                    "frames or a video)")
        ->type_name("A-B");
    render
        .add_option("--shard", f.shard,
                    "Render shard I of N (I from 0): every N-th frame of the range starting at "
                    "its I-th, so N jobs of an array render each frame once")
        ->type_name("I/N");
    render.add_flag("--overwrite", f.overwrite,
                    "Render frames whose files exist again (default: skip them, so a stopped "
                    "run resumes)");
    render.add_option("--fps", f.fps, "A video's frames per second")
        ->check(real_in(0.01, 1000))
        ->capture_default_str();
    render.add_flag("--side-by-side", f.side_by_side,
                    "With -m a,b,c: each frame the methods' pictures left to right, each under "
                    "its method's name, in the one output -o names (a video, or numbered 8-bit "
                    "pictures), so the methods compare frame by frame");
}

void check_frame_options(const CLI::App& render, RenderOptions& o) {
    FrameOptions& f = o.frames;
    f.frame_render = f.turntable > 0;
    if (!f.frame_render && asks_for_frames(render, o)) {
        const SceneFrames frames = read_animation(render, o);
        f.frame_render = frames != SceneFrames::none;
        if (frames == SceneFrames::unreadable) return;  // the load says why
    }
    if (!f.frame_render) {
        for (const char* flag : {"--frames", "--shard", "--overwrite", "--fps", "--side-by-side"})
            if (render.count(flag) > 0)
                throw CLI::ValidationError(fmt::format(
                    "{} is for an animation's frames: add --turntable N, or render a scene "
                    "with an \"animation\" block",
                    flag));
        for (const std::string& name : o.methods)
            if (is_video_path(output_for(o, name)))
                throw CLI::ValidationError(fmt::format(
                    "{}: a video needs frames: add --turntable N, or render a scene with an "
                    "\"animation\" block",
                    output_for(o, name)));
        return;
    }
    if (!f.range.empty()) check_frame_range(f);
    std::string why;
    if (!f.shard.empty() && !parse_frame_shard(f.shard, why))
        throw CLI::ValidationError(fmt::format("--shard {}: {}", f.shard, why));
    if (o.print_matrices) throw CLI::ValidationError("--print-matrices is for a single render");
    check_frame_outputs(o);
}

bool is_frame_render(const RenderOptions& o) { return o.frames.frame_render; }

}  // namespace hikari::cli
