#include "hikari/io/video/video_pipe.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "hikari/core/error.h"
#include "hikari/io/files/atomic_file.h"

extern char** environ;

namespace hikari {

namespace {

namespace fs = std::filesystem;

/// The extension of `path` in lower case.
std::string extension_of(const fs::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

/// ffmpeg's arguments after its input: the codec and the container for `path`'s extension
/// (given with -f, since the temporary it writes has no such extension).
std::vector<std::string> output_arguments(const fs::path& path) {
    const std::string ext = extension_of(path);
    if (ext == ".gif")
        // One palette from every frame (palettegen), then each frame dithered to it (paletteuse).
        return {"-filter_complex", "split[a][b];[a]palettegen[p];[b][p]paletteuse", "-f", "gif"};
    if (ext == ".webm") return {"-c:v", "libvpx-vp9", "-pix_fmt", "yuv420p", "-f", "webm"};
    return {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-f", "mp4"};
}

/// The whole ffmpeg command line: raw RGB24 frames on standard input, the video to `temporary`.
std::vector<std::string> ffmpeg_arguments(const fs::path& path, const fs::path& temporary,
                                          const VideoSettings& s) {
    std::vector<std::string> args{"ffmpeg",
                                  "-hide_banner",
                                  "-loglevel",
                                  "error",
                                  "-y",
                                  "-f",
                                  "rawvideo",
                                  "-pix_fmt",
                                  "rgb24",
                                  "-s",
                                  fmt::format("{}x{}", s.width, s.height),
                                  "-r",
                                  fmt::format("{}", s.fps),
                                  "-i",
                                  "-"};
    for (std::string& a : output_arguments(path)) args.push_back(std::move(a));
    args.push_back(temporary.string());
    return args;
}

/// Runs `args` with its standard input the read end of a new pipe; returns the write end.
int spawn_with_input_pipe(const fs::path& program, const std::vector<std::string>& args,
                          pid_t& process) {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0)
        throw InputError(fmt::format("cannot start ffmpeg: {}", std::strerror(errno)));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], STDIN_FILENO);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const int error =
        posix_spawn(&process, program.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[0]);
    if (error != 0) {
        ::close(fds[1]);
        throw InputError(
            fmt::format("cannot start {}: {}", program.string(), std::strerror(error)));
    }
    return fds[1];
}

/// Waits for `process`; its exit status, or 128 + the signal that ended it.
int wait_for(pid_t process) {
    int status = 0;
    while (::waitpid(process, &status, 0) < 0 && errno == EINTR) {
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

bool is_video_path(const fs::path& path) {
    const std::string ext = extension_of(path);
    return ext == ".mp4" || ext == ".webm" || ext == ".gif";
}

std::optional<fs::path> find_ffmpeg() {
    const char* path = std::getenv("PATH");
    std::string_view dirs = path ? path : "";
    while (!dirs.empty()) {
        const size_t colon = dirs.find(':');
        const fs::path candidate = fs::path(dirs.substr(0, colon)) / "ffmpeg";
        if (!candidate.parent_path().empty() && ::access(candidate.c_str(), X_OK) == 0)
            return candidate;
        dirs = colon == std::string_view::npos ? std::string_view() : dirs.substr(colon + 1);
    }
    return std::nullopt;
}

std::string missing_ffmpeg_message(const fs::path& video) {
    return fmt::format(
        "{}: writing a video needs the ffmpeg program, which is not on PATH; install it "
        "(Debian, Ubuntu: sudo apt-get install ffmpeg), or write the frames as images "
        "(-o frame_%04d.png)",
        video.string());
}

VideoPipe::VideoPipe(const fs::path& path, const VideoSettings& settings)
    : m_path(path), m_frame_bytes(static_cast<size_t>(settings.width) * settings.height * 3) {
    const std::optional<fs::path> ffmpeg = find_ffmpeg();
    if (!ffmpeg) throw InputError(missing_ffmpeg_message(path));
    remove_stale_temporary_files(path);
    m_temporary =
        path.parent_path() / fmt::format("{}{}-video.tmp", temporary_prefix_for(path), ::getpid());
    // A write to a pipe whose reader has gone must fail with EPIPE, not end this process.
    ::signal(SIGPIPE, SIG_IGN);
    m_input =
        spawn_with_input_pipe(*ffmpeg, ffmpeg_arguments(path, m_temporary, settings), m_process);
}

VideoPipe::~VideoPipe() { stop(); }

void VideoPipe::stop() noexcept {
    if (m_input >= 0) ::close(m_input);
    m_input = -1;
    if (m_process > 0) {
        ::kill(m_process, SIGKILL);
        wait_for(m_process);
    }
    m_process = -1;
    std::error_code ec;
    if (!m_temporary.empty()) fs::remove(m_temporary, ec);
}

void VideoPipe::write_frame(std::span<const uint8_t> rgb) {
    if (rgb.size() != m_frame_bytes)
        throw InputError(fmt::format("{}: a frame of {} bytes where the video takes {}",
                                     m_path.string(), rgb.size(), m_frame_bytes));
    const uint8_t* data = rgb.data();
    size_t left = rgb.size();
    while (left > 0) {
        const ssize_t n = ::write(m_input, data, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int status = (::close(m_input), m_input = -1, wait_for(m_process));
            m_process = -1;
            stop();
            throw InputError(
                fmt::format("{}: ffmpeg stopped (exit status {}) before the video "
                            "was whole; its messages are above",
                            m_path.string(), status));
        }
        data += n;
        left -= static_cast<size_t>(n);
    }
}

void VideoPipe::finish() {
    ::close(m_input);
    m_input = -1;
    const int status = wait_for(m_process);
    m_process = -1;
    std::error_code ec;
    if (status != 0) {
        stop();
        throw InputError(fmt::format("{}: ffmpeg failed (exit status {}); its messages are above",
                                     m_path.string(), status));
    }
    fs::rename(m_temporary, m_path, ec);
    if (ec) {
        stop();
        throw InputError(fmt::format("{}: cannot write: {}", m_path.string(), ec.message()));
    }
    m_temporary.clear();
}

}  // namespace hikari
