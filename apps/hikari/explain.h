#pragma once
// `hikari explain SCENE -m METHOD --row Y | --pixel X,Y`: one step of an algorithm, printed as it
// runs on the scene.

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "render_options.h"

namespace hikari::cli {

/// The options of `hikari explain`.
struct ExplainOptions {
    RenderOptions scene;  ///< the scene file, --set, --width, --height
    std::string method;
    std::optional<int> row;
    std::vector<int> pixel;  ///< X,Y
};

/// `hikari explain` and its options.
CLI::App* add_explain_command(CLI::App& app, ExplainOptions& e);

/// Prints the method's explanation on stdout; returns the exit status (0). Throws InputError
/// when the method's view needs --pixel or --row and it is missing, or as loading does.
int run_explain(const ExplainOptions& e);

}  // namespace hikari::cli
