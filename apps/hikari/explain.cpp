#include "explain.h"

#include <string_view>

#include <fmt/format.h>

#include "cli_options.h"
#include "console.h"
#include "hikari/core/error.h"
#include "hikari/methods/registry.h"
#include "hikari/session/session.h"
#include "load_scene.h"

namespace hikari::cli {

namespace {

/// The methods that have an explain view, e.g. "zbuffer, raytrace" for --pixel; `separator`
/// between them.
template <class View>
std::string methods_with(View ExplainViews::*view, std::string_view separator) {
    std::string list;
    for (const Method& m : methods())
        if (m.explain.*view) list += fmt::format("{}{}", list.empty() ? "" : separator, m.name);
    return list;
}

/// -m's help: which method takes --pixel, which --row, which explains the whole scene.
std::string method_help() {
    return fmt::format("{} (with --pixel), {} (with --row), or {} (the whole sort)",
                       methods_with(&ExplainViews::pixel, " or "),
                       methods_with(&ExplainViews::row, " or "),
                       methods_with(&ExplainViews::whole, " or "));
}

/// The methods `hikari explain` takes: those whose registry entry has a view.
std::vector<std::string> explained_methods() {
    std::vector<std::string> names;
    for (const Method& m : methods())
        if (has_explain_view(m)) names.emplace_back(m.name);
    return names;
}

}  // namespace

CLI::App* add_explain_command(CLI::App& app, ExplainOptions& e) {
    CLI::App* explain = app.add_subcommand(
        "explain",
        "Print a hidden-surface algorithm's work as it runs on a scene: the Z-buffer's "
        "fragments at a pixel (Alg 4.2), the scanline method's edge table, active edge list "
        "and sample spans at a row (Alg 4.1), or the depth sort's comparisons, reorderings, "
        "splits and painting order (Fig 4.6-4.9), or the ray tracer's ray tree at a pixel "
        "(Alg 4.3).");
    explain->add_option("scene", e.scene.scene_file,
                        "Scene file (default: the lecture's assignment)");
    explain->add_option("-m,--method", e.method, method_help())
        ->required()
        ->check(CLI::IsMember(explained_methods()));
    explain
        ->add_option("--row", e.row,
                     methods_with(&ExplainViews::row, ", ") + ": the row (0 at the top)")
        ->check(whole_in(0, 65535));
    explain
        ->add_option(
            "--pixel", e.pixel,
            methods_with(&ExplainViews::pixel, ", ") + ": the pixel X,Y (0,0 at the top left)")
        ->delimiter(',')
        ->expected(2)
        ->type_name("X,Y")
        ->check(whole_in(0, 65535));
    explain->add_option("--width", e.scene.width, "Image width in pixels (overrides the scene)")
        ->check(whole_in(1, 65536));
    explain->add_option("--height", e.scene.height, "Image height in pixels (overrides the scene)")
        ->check(whole_in(1, 65536));
    explain
        ->add_option_function<int>(
            "--max-depth", [&e](int d) { e.scene.own.max_depth = d; },
            "raytrace: ray segments per path, the camera ray included (default 5)")
        ->check(whole_in(1, 64));
    add_set_option(*explain, e.scene.overrides);
    add_max_memory_option(*explain, "scenes and ray trees");
    return explain;
}

int run_explain(const ExplainOptions& e) {
    const std::unique_ptr<Session> session = load_render_session(e.scene);
    ExplainStep step;
    if (!e.pixel.empty()) step.pixel = std::pair{e.pixel[0], e.pixel[1]};
    step.row = e.row;
    RenderRequest request = render_request(e.scene);
    request.method = e.method;
    print_out("{}", session->explain(request, step));
    return 0;
}

}  // namespace hikari::cli
