#include "progress.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>

#include <fmt/format.h>

#include "console.h"
#include "signals.h"

namespace hikari::cli {

namespace {

using Clock = std::chrono::steady_clock;

/// The line for `stage` after `elapsed` seconds: a bar, the rate and the time left when the
/// work is measured (`pixels` > 0 and the method has said how much there is), else the time.
std::string progress_line(const std::string& stage, double pixels, double elapsed) {
    const RenderControl& control = render_control();
    const uint64_t total = control.work_total.load();
    if (pixels <= 0.0 || total == 0)
        return fmt::format("\rhikari: {} ... {:.1f} s ", stage, elapsed);
    const double done = static_cast<double>(control.work_done.load()) / total;
    const double eta = done > 0 ? elapsed * (1.0 - done) / done : 0.0;
    constexpr int k_bar = 24;
    const int filled = std::clamp(static_cast<int>(done * k_bar), 0, k_bar);
    return fmt::format(
        "\rhikari: {} [{}{}] {:5.1f}%  {:.2f} Mpixel/s  {:.1f} s elapsed, ~{:.1f} s left ", stage,
        std::string(filled, '#'), std::string(k_bar - filled, '.'), 100.0 * done,
        1e-6 * done * pixels / elapsed, elapsed, eta);
}

}  // namespace

ProgressReporter::ProgressReporter(bool enabled, std::string stage, double pixels) {
    if (!enabled || !isatty(STDERR_FILENO)) return;
    m_thread = std::jthread([stage = std::move(stage), pixels](const std::stop_token& stop) {
        const auto start = Clock::now();
        bool shown = false;
        while (!stop.stop_requested()) {
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
            const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
            if (elapsed < 1.0) continue;
            try {
                write_err(progress_line(stage, pixels, elapsed));
            } catch (...) {  // no memory for the line: the next tick tries again
            }
            shown = true;
        }
        if (shown) write_err("\r\033[K");
    });
}

}  // namespace hikari::cli
