#pragma once
// `hikari render`: every method asked for, in turn, on one load of the scene. Its steps are
// separate functions (load_scene.h loads, render.cpp renders, render_output.h writes), so that a
// render session can take the middle one's place.

#include "render_options.h"

namespace hikari::cli {

/// Checks every output before any work is done (output_paths.h), loads the scene once, prints
/// --print-matrices on stdout, then renders each method into its output and reports on stderr.
/// Returns the exit status (0); throws UsageError, InputError or Interrupted.
int run_render(const RenderOptions& o);

}  // namespace hikari::cli
