#pragma once
// The program's two streams. Every line hikari prints goes through here, so that a closed or full
// stdout or stderr never aborts it (the formatting library throws on a failed write): a line that
// cannot reach stderr is dropped, as there is nowhere left to say so, and the command's work goes
// on but it ends with exit status 1; a report that cannot reach stdout (`info`, `compare`,
// `explain`, `bench`, `--print-matrices`) ends the command with exit status 1 and, where stderr
// still works, a line saying why.

#include <cerrno>
#include <string_view>
#include <utility>

#include <fmt/format.h>

namespace hikari::cli {

/// Keeps descriptors 0, 1 and 2 taken: one the shell left closed is opened on /dev/null
/// (read-only, so that a write there fails as on a closed stream), so that no file the program
/// opens later gets a standard stream's number and receives its lines.
void reserve_standard_streams() noexcept;

/// Writes `text` to stderr; a failed write is dropped and remembered for finish_standard_output.
void write_err(std::string_view text) noexcept;

/// Writes `text` to stdout; a failed write is remembered for finish_standard_output.
void write_out(std::string_view text) noexcept;

/// Remembers a failed write to stdout (`error`: an errno value, or -1 when the reason is lost).
void note_stdout_failure(int error) noexcept;

/// fmt::print(stderr, ...) that never throws.
template <class... Args>
void print_err(fmt::format_string<Args...> format, Args&&... args) noexcept {
    try {
        write_err(fmt::format(format, std::forward<Args>(args)...));
    } catch (...) {  // out of memory for the line: drop it too
    }
}

/// fmt::print(stdout, ...) that never throws; see finish_standard_output.
template <class... Args>
void print_out(fmt::format_string<Args...> format, Args&&... args) noexcept {
    try {
        write_out(fmt::format(format, std::forward<Args>(args)...));
    } catch (...) {  // out of memory for the report: it is incomplete
        note_stdout_failure(ENOMEM);
    }
}

/// Flushes stdout and returns the command's exit status: `status`, or 1 when a command that
/// otherwise succeeded could not write all it printed on stdout (with `hikari: error: cannot
/// write to standard output: <reason>` on stderr, the reason where it is known) or on stderr.
int finish_standard_output(int status) noexcept;

}  // namespace hikari::cli
