#pragma once
// `hikari render --turntable N` or `--frames A-B` of a scene's "animation" block: its frames from
// one load of the scene (a render session): each frame one Session::render with that frame's
// camera, written to its numbered file (`-o out/frame_%04d.png`) or piped into one video (`-o
// turntable.mp4`). Frames whose files exist are skipped, so a stopped run resumes; `--shard I/N`
// splits the frames among jobs.

#include <CLI/CLI.hpp>

#include "render_options.h"

namespace hikari::cli {

/// --turntable, --frames, --shard, --overwrite and --fps.
void add_frame_options(CLI::App& render, FrameOptions& f);

/// Usage errors (CLI::ValidationError) of the frame options: a bad range or shard, frames beyond
/// the animation, a frame output without a frame number, a video without frames or in shards.
/// Decides whether the options render frames (--turntable, or a frame option, video or numbered
/// output for a scene with an "animation" block) and keeps the animation's frames in `o`.
void check_frame_options(const CLI::App& render, RenderOptions& o);

/// Whether the options ask for an animation's frames rather than one still.
bool is_frame_render(const RenderOptions& o);

/// Renders this process's frames for every method asked for; returns the exit status (0).
/// Throws UsageError, InputError or Interrupted, as run_render does.
int run_frame_render(const RenderOptions& o);

}  // namespace hikari::cli
