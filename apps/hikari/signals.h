#pragma once
// How a run ends: the exit statuses, and SIGINT / SIGTERM stopping every stage cleanly.

#include <sys/types.h>

#include "hikari/frame/render_settings.h"

namespace hikari::cli {

/// Exit statuses: 1 for bad input or a failed render, 2 for command-line usage errors, 128 + the
/// signal's number when SIGINT (130) or SIGTERM (143) stops the run.
constexpr int k_exit_input_error = 1;
constexpr int k_exit_usage_error = 2;

/// The progress counters of the running render and the cancel flag the first signal sets.
RenderControl& render_control() noexcept;

/// Names the child process running now (`gallery`'s renders), 0 for none: when the run must
/// leave at once (a second signal, or the first one's alarm), the child is ended and waited for
/// first, so that nothing goes on writing after hikari has gone.
void set_child_process(pid_t child) noexcept;

/// The first SIGINT or SIGTERM received (SIGINT when none was), to pass on to a child.
int first_signal() noexcept;

/// 128 + the signal that stopped the run (130 for SIGINT, 143 for SIGTERM), as a shell reports
/// a process killed by it.
int interrupted_status() noexcept;

/// Prints `hikari: interrupted` on stderr, once whichever path gets there first (the render's
/// unwinding or the handler's fallback). Async-signal-safe: write(2) on a constant.
void report_interrupted() noexcept;

/// Installed first thing, so that a signal at any stage (parsing included) ends the same way.
void install_signal_handlers();

}  // namespace hikari::cli
