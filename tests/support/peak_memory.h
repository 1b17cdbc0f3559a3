#pragma once
// The peak memory of one piece of work, measured in a child process (getrusage's ru_maxrss is a
// high-water mark of the whole process, so the test's own earlier peaks would hide the work's).

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "hikari/core/error.h"

namespace hikari::testing {

/// What a child that ran `work` reported: the memory its peak took beyond what it inherited
/// (the parent's resident memory at the fork), and whether `work` threw InputError (exit 1) or
/// returned (exit 0); `exit_code` is -1 when it crashed.
struct ChildRun {
    double extra_peak_bytes = 0;
    int exit_code = -1;
};

/// The resident memory of this process now, in bytes (Linux /proc/self/statm).
inline double resident_bytes() {
    long pages_total = 0, pages_resident = 0;
    if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%ld %ld", &pages_total, &pages_resident) != 2) pages_resident = 0;
        std::fclose(f);
    }
    return static_cast<double>(pages_resident) * static_cast<double>(::sysconf(_SC_PAGESIZE));
}

/// Runs `work` in a forked child and returns its peak memory and exit status. Only for
/// single-threaded work: the child has the parent's memory but only the forking thread.
template <class F>
ChildRun run_in_child(F&& work) {
    const double inherited = resident_bytes();
    const pid_t pid = ::fork();
    if (pid == 0) {
        int code = 0;
        try {
            work();
        } catch (const InputError&) {
            code = 1;
        } catch (...) {
            code = 2;
        }
        std::_Exit(code);
    }
    ChildRun run;
    int status = 0;
    rusage usage{};
    if (pid < 0 || ::wait4(pid, &status, 0, &usage) != pid) return run;
    run.extra_peak_bytes = static_cast<double>(usage.ru_maxrss) * 1024.0 - inherited;  // Linux: KiB
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return run;
}

}  // namespace hikari::testing
