#include "signals.h"

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>

#include "hikari/core/cancel.h"
#include "hikari/io/files/atomic_file.h"

namespace hikari::cli {

namespace {

RenderControl g_control;
// Lock-free atomics are safe to touch from a signal handler.
std::atomic<int> g_signal_count{0};
std::atomic<int> g_first_signal{0};  // SIGINT or SIGTERM, the first one received; 0: none
std::atomic<bool> g_interrupt_reported{false};
std::atomic<pid_t> g_child{0};  // the child process running now (gallery renders); 0: none

// The first SIGINT or SIGTERM asks every stage to stop (the render, and through core/cancel.h
// the loaders, the BVH build and the encoders, which then unwind writing nothing), and arms a
// one-second alarm in case the running stage does not poll (a codec inside a library call). On
// a second signal, or when the alarm rings, leave at once, removing any half-written temporary
// file. Either way the status is 128 + the first signal and the one line is printed.
extern "C" void exit_now(int) {
    // A child would go on writing after its parent is gone: end it first. It gets SIGTERM, so
    // it removes its own temporaries, and its own alarm bounds the wait.
    if (const pid_t child = g_child.load(); child > 0) {
        kill(child, SIGTERM);
        while (waitpid(child, nullptr, 0) == -1 && errno == EINTR) {
        }
    }
    remove_pending_temporary_files();
    report_interrupted();
    _exit(interrupted_status());
}

extern "C" void on_interrupt(int sig) {
    int none = 0;
    g_first_signal.compare_exchange_strong(none, sig);
    g_control.cancel.store(true);
    request_cancel();
    if (g_signal_count.fetch_add(1) > 0) exit_now(sig);
    alarm(1);
}

}  // namespace

RenderControl& render_control() noexcept { return g_control; }

void set_child_process(pid_t child) noexcept { g_child.store(child); }

int first_signal() noexcept {
    const int sig = g_first_signal.load();
    return sig != 0 ? sig : SIGINT;
}

int interrupted_status() noexcept {
    const int sig = g_first_signal.load();
    return 128 + (sig != 0 ? sig : SIGINT);
}

void report_interrupted() noexcept {
    if (g_interrupt_reported.exchange(true)) return;
    static constexpr char k_line[] = "hikari: interrupted\n";
    [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, k_line, sizeof k_line - 1);
}

void install_signal_handlers() {
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    action.sa_handler = exit_now;
    sigaction(SIGALRM, &action, nullptr);
}

}  // namespace hikari::cli
