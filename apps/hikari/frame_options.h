#pragma once
// The options of `hikari render` that make it render an animation's frames (render_frames.h).

#include <string>

namespace hikari::cli {

/// `--turntable`, `--frames`, `--shard`, `--overwrite` and `--fps`, as given.
struct FrameOptions {
    int turntable = 0;       ///< --turntable N: frames of one turn of the camera; 0: none
    std::string range;       ///< --frames A-B; empty: every frame
    std::string shard;       ///< --shard I/N; empty: every frame of the range
    bool overwrite = false;  ///< --overwrite: render frames whose files exist again
    double fps = 30;         ///< --fps: a video's frame rate
};

}  // namespace hikari::cli
