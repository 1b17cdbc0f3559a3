#pragma once
// Video files (.mp4, .webm, .gif) written by the `ffmpeg` program (Debian's package ffmpeg):
// raw RGB frames piped to its standard input as they are rendered, so no frame ever touches the
// disk. ffmpeg writes a temporary beside the target, renamed over it once the video is whole.

#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

namespace hikari {

/// Whether `path` names a video hikari writes through ffmpeg (.mp4, .webm or .gif).
bool is_video_path(const std::filesystem::path& path);

/// The `ffmpeg` program on PATH, or nullopt.
std::optional<std::filesystem::path> find_ffmpeg();

/// The message for a missing ffmpeg: what to install.
std::string missing_ffmpeg_message(const std::filesystem::path& video);

/// What a video is made of.
struct VideoSettings {
    int width = 0, height = 0;  ///< pixels of every frame (even for .mp4: H.264 in yuv420p)
    double fps = 30;            ///< frames per second
};

/// One ffmpeg process encoding one video: .mp4 as H.264 in yuv420p (what every player plays),
/// .webm as VP9 in yuv420p, .gif through a palette made from all the frames. Not copyable.
class VideoPipe {
  public:
    /// Starts ffmpeg writing `path` (a temporary beside it until finish()). Throws InputError
    /// when ffmpeg is missing or cannot start.
    VideoPipe(const std::filesystem::path& path, const VideoSettings& settings);
    /// Without finish(): stops ffmpeg and removes the temporary, leaving no partial video.
    ~VideoPipe();
    VideoPipe(const VideoPipe&) = delete;
    VideoPipe& operator=(const VideoPipe&) = delete;

    /// Sends one frame: width × height RGB triples, 8-bit sRGB, row 0 at the top. Throws
    /// InputError when ffmpeg has stopped (its own messages are on stderr above).
    void write_frame(std::span<const uint8_t> rgb);
    /// Ends the input, waits for ffmpeg and renames the finished video over the target. Throws
    /// InputError (removing the temporary) when ffmpeg failed.
    void finish();

  private:
    void stop() noexcept;

    std::filesystem::path m_path, m_temporary;
    size_t m_frame_bytes = 0;
    int m_input = -1;  ///< the pipe to ffmpeg's standard input
    pid_t m_process = -1;
};

}  // namespace hikari
