#include "explain.h"

#include "cli_options.h"
#include "console.h"
#include "hikari/core/error.h"
#include "hikari/explain/explain.h"
#include "load_scene.h"

namespace hikari::cli {

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
    explain
        ->add_option("-m,--method", e.method,
                     "zbuffer or raytrace (with --pixel), scanline (with --row), or depthsort "
                     "(the whole sort)")
        ->required()
        ->check(CLI::IsMember({"zbuffer", "scanline", "depthsort", "raytrace"}));
    explain->add_option("--row", e.row, "scanline: the row (0 at the top)")
        ->check(whole_in(0, 65535));
    explain
        ->add_option("--pixel", e.pixel, "zbuffer, raytrace: the pixel X,Y (0,0 at the top left)")
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
    return explain;
}

int run_explain(const ExplainOptions& e) {
    const Scene scene = load_render_scene(e.scene);
    const RasterSettings raster = e.scene.own.raster;
    if (e.method == "zbuffer") {
        if (e.pixel.empty()) throw InputError("explain -m zbuffer needs --pixel X,Y");
        print_out("{}", explain_zbuffer_pixel(scene, raster, e.pixel[0], e.pixel[1]));
    } else if (e.method == "raytrace") {
        if (e.pixel.empty()) throw InputError("explain -m raytrace needs --pixel X,Y");
        WhittedSettings whitted = e.scene.own.whitted;
        if (e.scene.own.max_depth) whitted.max_depth = *e.scene.own.max_depth;
        print_out("{}", explain_raytrace_pixel(scene, whitted, e.pixel[0], e.pixel[1]));
    } else if (e.method == "depthsort") {
        print_out("{}", explain_depth_sort(scene, raster));
    } else {
        if (!e.row) throw InputError("explain -m scanline needs --row Y");
        print_out("{}", explain_scanline_row(scene, raster, *e.row));
    }
    return 0;
}

}  // namespace hikari::cli
