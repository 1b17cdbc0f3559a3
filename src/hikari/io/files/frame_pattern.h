#pragma once
// The file name of each frame of an animation: a printf-style pattern with one frame number in
// it, `out/frame_%04d.png` (as ffmpeg, Blender's `#` and POV-Ray's numbered outputs do).

#include <optional>
#include <string>
#include <string_view>

namespace hikari {

/// A parsed frame pattern: the text before and after its one `%d` or `%0Nd`.
struct FramePattern {
    std::string before, after;  ///< `%%` already turned into `%`
    int digits = 0;             ///< N of `%0Nd`: the number is padded with zeros to N digits

    /// The file name of frame `frame` (≥ 0).
    std::string file_name(int frame) const;
};

/// `pattern` parsed, or nullopt with `why` saying what is wrong: no frame number in it, two of
/// them, or a `%` that is neither `%d`, `%0Nd` (N from 1 to 9) nor `%%`.
std::optional<FramePattern> parse_frame_pattern(std::string_view pattern, std::string& why);

}  // namespace hikari
