#pragma once
// The methods on `hikari render`'s command line: every method's own options (from the registry),
// the --help list of methods, and the usage errors of options a method cannot take.

#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

#include "hikari/methods/registry.h"
#include "render_options.h"

namespace hikari::cli {

/// Every method option, in a --help group headed by the methods that understand it.
void add_method_options(CLI::App& render, MethodSettings& own);

/// The --help footer: every method, and the options it understands beside the common ones.
std::string method_list();

/// Usage errors (CLI::ValidationError) of the methods asked for: an option or --aov that the one
/// method cannot take; with several methods, an option none of them takes (the others are told,
/// in o.notes, it is not theirs) and the same method twice.
void check_render_methods(const CLI::App& render, RenderOptions& o);

}  // namespace hikari::cli
