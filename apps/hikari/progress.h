#pragma once
// The progress line on stderr while a long stage runs.

#include <string>
#include <thread>

namespace hikari::cli {

/// Prints a progress line on stderr, once a stage has taken a second, when stderr is a terminal:
/// for a render a bar with the percentage done, the rate in pixels per second and the time left
/// (`pixels` > 0, read from render_control()'s counters); for a load (`pixels` = 0, no measure
/// of the work) the time so far. The line is erased when the reporter goes out of scope.
class ProgressReporter {
  public:
    ProgressReporter(bool enabled, std::string stage, double pixels);

  private:
    std::jthread m_thread;
};

}  // namespace hikari::cli
