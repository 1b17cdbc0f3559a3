#pragma once
// Running the hikari program from a test: its exit status and everything it printed.

#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace hikari::testing {

struct RunResult {
    int status;          ///< the exit status, or 128 + the signal that ended it
    std::string output;  ///< stdout and stderr together
};

/// Runs `hikari ARGS REDIRECTIONS` (a shell command line) and waits for it; `output` is what
/// reached the pipe that stdout starts on (redirections "2>&1 >/dev/full": stderr alone).
inline RunResult run_hikari_redirected(const std::string& args, const std::string& redirections) {
    const std::string command = std::string(HIKARI_CLI_PATH) + " " + args + " " + redirections;
    FILE* pipe = popen(command.c_str(), "r");
    std::string output;
    char buffer[4096];
    while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) output.append(buffer, n);
    const int raw = pclose(pipe);
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw), output};
}

/// Runs `hikari ARGS` (a shell command line) and waits for it.
inline RunResult run_hikari(const std::string& args) { return run_hikari_redirected(args, "2>&1"); }

/// Runs a shell command line (ffmpeg, ffprobe, an environment for hikari) and waits for it; its
/// exit status and output (stdout and stderr together).
inline RunResult run_shell(const std::string& command) {
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    std::string output;
    char buffer[4096];
    while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) output.append(buffer, n);
    const int raw = pclose(pipe);
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw), output};
}

}  // namespace hikari::testing
