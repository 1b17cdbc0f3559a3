#pragma once
// `hikari render` on the command line: its options, and the usage errors found once they are
// parsed.

#include <CLI/CLI.hpp>

#include "render_options.h"

namespace hikari::cli {

/// `hikari render` and the options every method takes; the methods' own come after them.
CLI::App* add_render_command(CLI::App& app, RenderOptions& o);

/// Usage errors (CLI::ValidationError) of a parsed render command line: options the methods
/// cannot take, ranges backwards, options that contradict each other or the outputs. Adds notes
/// for options that do nothing here.
void check_render_command(const CLI::App& render, RenderOptions& o);

}  // namespace hikari::cli
