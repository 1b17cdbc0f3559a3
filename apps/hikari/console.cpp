#include "console.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace hikari::cli {

namespace {

/// The errno of the first write to stdout that failed; 0: none did.
int g_stdout_error = 0;

/// Whether a write to stderr failed (a line lost: the exit status says so, as GNU's
/// close_stdout does, since no line can).
std::atomic<bool> g_stderr_failed{false};

/// Writes `text` to `stream`, the errno of the failure or 0.
int write_to(std::FILE* stream, std::string_view text) noexcept {
    if (text.empty()) return 0;
    errno = 0;
    if (std::fwrite(text.data(), 1, text.size(), stream) == text.size()) return 0;
    return errno != 0 ? errno : EIO;
}

}  // namespace

void reserve_standard_streams() noexcept {
    for (int fd = 0; fd <= 2; ++fd) {
        if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
        // open() takes the lowest free number, which is `fd` while the ones below are taken.
        const int opened = ::open("/dev/null", O_RDONLY);
        if (opened >= 0 && opened != fd) ::close(opened);
    }
}

void write_err(std::string_view text) noexcept {
    if (write_to(stderr, text) != 0) g_stderr_failed.store(true);
}

void write_out(std::string_view text) noexcept {
    if (const int error = write_to(stdout, text); error != 0) note_stdout_failure(error);
}

void note_stdout_failure(int error) noexcept {
    if (g_stdout_error == 0) g_stdout_error = error;
}

int finish_standard_output(int status) noexcept {
    errno = 0;
    // A write that failed inside a stream flush (std::cout's, CLI11's --help) leaves the stream's
    // error flag but not its reason.
    if (std::fflush(stdout) != 0 || std::ferror(stdout))
        note_stdout_failure(errno != 0 ? errno : -1);
    if (status != 0) return status;
    if (g_stdout_error == 0) return g_stderr_failed.load() ? 1 : 0;
    if (g_stdout_error < 0)
        print_err("hikari: error: cannot write to standard output\n");
    else
        print_err("hikari: error: cannot write to standard output: {}\n",
                  std::strerror(g_stdout_error));
    return 1;
}

}  // namespace hikari::cli
