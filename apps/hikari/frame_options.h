#pragma once
// The options of `hikari render` that make it render an animation's frames (render_frames.h).

#include <string>

namespace hikari::cli {

/// `--turntable`, `--frames`, `--shard`, `--overwrite`, `--fps` and `--side-by-side`, as given.
struct FrameOptions {
    int turntable = 0;       ///< --turntable N: frames of one turn of the camera; 0: none
    std::string range;       ///< --frames A-B; empty: every frame
    std::string shard;       ///< --shard I/N; empty: every frame of the range
    bool overwrite = false;  ///< --overwrite: render frames whose files exist again
    double fps = 30;         ///< --fps: a video's frame rate (an animation's own without it)
    /// --side-by-side: every method's picture of a frame in one labelled picture (-o as given)
    bool side_by_side = false;
    /// Found by check_frame_options: whether to render frames, not a still, and the frames of
    /// the scene's "animation" block (0: none, or a --turntable run).
    bool frame_render = false;
    int animation_frames = 0;
};

/// The frames of the turntable or of the scene's animation.
inline int frame_count(const FrameOptions& f) {
    return f.turntable > 0 ? f.turntable : f.animation_frames;
}

}  // namespace hikari::cli
