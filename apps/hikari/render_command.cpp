#include "render_command.h"

#include <cmath>
#include <tuple>

#include <fmt/format.h>

#include "cli_options.h"
#include "hikari/io/images/image_format.h"
#include "hikari/io/images/image_write.h"
#include "hikari/io/images/svg_write.h"
#include "hikari/scene/scene.h"
#include "output_paths.h"
#include "render_frames.h"
#include "render_methods.h"

namespace hikari::cli {

namespace {

/// Scene, output and method: the first of the render options.
void add_render_inputs(CLI::App& render, RenderOptions& o) {
    render.add_option("scene", o.scene_file,
                      "Scene file (JSON, see docs/scene-format.md), or a model file (.obj, "
                      ".ply, .gltf, .glb) rendered with a camera framed on it and default "
                      "lights; default: the lecture's assignment, a Phong-shaded sphere");
    render.add_option("-o,--output", o.output,
                      "Output image: .png or .ppm (sRGB, 8 or 16 bits, see --bit-depth), .jpg "
                      "(8-bit sRGB, quality 95), .pfm, .exr or .hdr (linear, unclamped), .xlsx (a "
                      "spreadsheet whose cells are the pixels), or .svg (the segments of "
                      "wireframe and hiddenline); default: <scene name>.png (raytrace) or "
                      "<scene name>-<method>.png in the current directory");
    std::vector<std::string> names;
    for (const Method& m : methods()) names.emplace_back(m.name);
    render
        .add_option("-m,--method", o.methods,
                    "Rendering method, or several separated by commas (-m zbuffer,scanline,"
                    "raytrace: one scene load, one image per method, <scene>-<method>.png)")
        ->delimiter(',')
        ->check(CLI::IsMember(names))
        ->default_str(std::string(methods().front().name));
    add_choice_option<Aov>(
        render, "--aov",
        "Buffer to write: color; depth (eye distance), id (1 + primitive index, 0 = background), "
        "normal -- raw values in .pfm/.exr/.hdr, pictures in .png/.jpg/.ppm (depth near white "
        "to far black, ids in false colour, normals as 0.5 + 0.5n); ambient, diffuse, specular: "
        "one term of the shading model alone (Fig 4.29; the three sum to color); overdraw "
        "(zbuffer, depthsort), paint-order (depthsort), spans (scanline), culled (raster "
        "methods): the algorithm at work",
        k_aov_choices, o.aov);
}

/// --width, --height, --threads and the limits on memory and input sizes.
void add_size_options(CLI::App& render, RenderOptions& o) {
    render.add_option("--width", o.width, "Image width in pixels (overrides the scene)")
        ->check(whole_in(1, 65536));
    render.add_option("--height", o.height, "Image height in pixels (overrides the scene)")
        ->check(whole_in(1, 65536));
    render.add_option("--threads", o.threads, "Worker threads (default: all cores)")
        ->check(whole_in(1, 1024));
    render
        .add_option("--max-memory", o.max_memory_gib,
                    "Refuse renders whose buffers need more than this many GiB "
                    "(default: half the machine's memory)")
        ->check(real_in(k_least_positive, k_max_real, "a positive number of GiB"));
    render
        .add_option("--max-input-size", o.max_input_gib,
                    "Refuse input files (scene, mesh, texture, environment map) larger than this "
                    "many GiB (default: 0.25 for a scene, 4 for a mesh, 1 for an image)")
        ->check(real_in(1.0 / (1 << 30), 1 << 20, "a positive number of GiB"));
}

/// --depth-cue and --depth-range: distances NEAR,FAR.
void add_depth_options(CLI::App& render, RenderOptions& o) {
    for (auto [flag, field, help] : {
             std::tuple{"--depth-cue", &o.depth_cue,
                        "Depth cueing (Fig 4.1b) from eye distance NEAR to FAR: the colour blends "
                        "toward the cue colour (the scene's depth_cue.color, else the background) "
                        "as w·colour + (1−w)·cue, w = clamp((FAR−d)/(FAR−NEAR), 0, 1)"},
             std::tuple{"--depth-range", &o.depth_range,
                        "--aov depth in a picture file: eye distance NEAR is white, FAR black "
                        "(default: the nearest and farthest visible points), so that several "
                        "images share one scale"},
         })
        render.add_option(flag, *field, help)
            ->delimiter(',')
            ->expected(2)
            ->type_name("NEAR,FAR")
            ->check(real_in(0, k_max_real, "a distance of at least 0"));
}

/// `--exposure`, `--tonemap` and `--bit-depth`: how the colour is developed into the file.
void add_output_development_options(CLI::App& render, RenderOptions& o) {
    render
        .add_option("--exposure", o.exposure,
                    "Multiply the linear colour by 2^EV before writing it, in every format "
                    "(floats included; the render itself is unchanged; not the --aov buffers)")
        ->type_name("EV")
        ->check(real_in(-100, 100))
        ->capture_default_str();
    add_choice_option<ToneMap>(
        render, "--tonemap",
        "How colour above 1 reaches a PNG, JPEG, PPM or spreadsheet (after --exposure; float "
        "files keep radiance): clamp (clip to white, per channel), reinhard (c/(1+c), Reinhard et "
        "al. 2002), aces (Narkowicz's 2015 fit of the ACES filmic curve)",
        k_tone_map_choices, o.tone_map);
    render
        .add_option("--bit-depth", o.bit_depth,
                    "Bits per sample of the sRGB files: 8, or 16 for .png and .ppm")
        ->check(CLI::Validator(
            [](const std::string& bits) {
                return bits == "8" || bits == "16" ? std::string()
                                                   : std::string("expected 8 or 16");
            },
            "8|16"))
        ->capture_default_str();
    add_choice_option<SampleEncoding>(
        render, "--encoding",
        "How .png, .ppm, .jpg and .xlsx hold linear values: srgb (the sRGB curve, what screens "
        "expect) or linear (round(255 v), as the lecture's sample code writes; looks darker)",
        k_sample_encoding_choices, o.encoding);
}

/// The options for rendering a model file (.obj, .ply, .gltf, .glb) as a scene of its own, and
/// for placing the camera of any scene.
void add_model_options(CLI::App& render, RenderOptions& o) {
    render.add_flag("--ground", o.ground,
                    "With a model file: a checkered ground plane just under the model");
    for (auto [flag, field, what] :
         {std::tuple{"--camera-from", &o.camera_from, "Put the camera's eye at X,Y,Z"},
          std::tuple{"--look-at", &o.look_at, "Point the camera at X,Y,Z"}})
        render
            .add_option(flag, *field,
                        std::string(what) + " (overrides the scene's camera or a model's framing)")
            ->delimiter(',')
            ->expected(3)
            ->type_name("X,Y,Z")
            ->check(real_in(-k_max_real, k_max_real));
    render
        .add_option("--crease-angle", o.crease_angle,
                    "Meshes without normals: smooth across edges whose faces meet at less than "
                    "this many degrees, split the normals elsewhere (0: flat faces, Fig 4.5; "
                    "180: smooth everywhere; default: each mesh's \"crease_angle\", else 45)")
        ->check(real_in(0, 180));
}

/// --print-matrices, --tessellation, --wireframe-overlay, --quiet and --stats.
void add_extra_options(CLI::App& render, RenderOptions& o) {
    render.add_flag("--print-matrices", o.print_matrices,
                    "Print M, P and V of p_s = V P M p_w for the scene's camera, and one vertex "
                    "of each object carried through them (stdout), then render");
    render
        .add_option("--tessellation", o.tessellation,
                    "Polygons around every sphere's equator when a raster method tessellates "
                    "it (overrides the scene's \"segments\"; default: fine enough for its size "
                    "on screen)")
        ->check(whole_in(k_min_sphere_segments, k_max_sphere_segments));
    render.add_flag("--wireframe-overlay", o.wireframe_overlay,
                    "Draw every triangle's edges over the image: the triangles the raster "
                    "methods fill (spheres and planes tessellated as they tessellate them)");
    render.add_flag("--formulas", o.formulas,
                    "With -o FILE.xlsx: a workbook whose cells compute the picture with "
                    "spreadsheet formulas (ray-sphere, Lambert, Phong) from parameter cells, "
                    "instead of holding rendered pixels (one sphere, one directional light)");
    render.add_flag("-q,--quiet", o.quiet, "No progress or summary on stderr");
    render.add_flag(
        "--stats", o.stats,
        "Print the load, render and write times, rays (and paths) per second and BVH figures "
        "on stderr");
}

/// Usage errors of --bit-depth, --exposure and --tonemap against the outputs; notes where they
/// do nothing.
void check_output_development(const CLI::App& render, RenderOptions& o) {
    if (std::isnan(o.exposure)) throw CLI::ValidationError("--exposure: EV must be a number");
    const bool developed = render.count("--exposure") > 0 || render.count("--tonemap") > 0;
    if (developed && !is_colour_aov(o.aov))
        o.notes.push_back(fmt::format(
            "--exposure and --tonemap develop colour renders; --aov {} is written as is",
            aov_name(o.aov)));
    for (const std::string& name : o.methods) {
        const std::string output = output_for(o, name);
        if (!supports_bit_depth(output, o.bit_depth))
            throw CLI::ValidationError(
                fmt::format("--bit-depth {}: {} cannot hold it (16 bits are for .png and .ppm)",
                            o.bit_depth, output));
        if (render.count("--tonemap") > 0 && !is_picture_file(output) && !is_svg_path(output))
            o.notes.push_back(fmt::format(
                "--tonemap is for pictures (.png, .jpg, .ppm, .xlsx); {} keeps linear radiance",
                output));
    }
}

/// --formulas: a workbook that computes the ray tracer's colour, so an .xlsx output, raytrace,
/// the colour at one sample, nothing developed.
void check_formulas(const CLI::App& render, const RenderOptions& o) {
    if (!o.formulas) return;
    const auto refuse = [](std::string_view why) {
        throw CLI::ValidationError("--formulas: " + std::string(why));
    };
    // The registry's first method is Whitted ray tracing, the assignment's (and the default).
    const std::string_view ray_tracer = methods().front().name;
    if (o.methods.size() != 1 || o.methods.front() != ray_tracer)
        refuse(fmt::format("the workbook computes the ray tracer's picture (-m {})", ray_tracer));
    if (image_format_from_extension(output_for(o, o.methods.front())) != ImageFormat::Xlsx)
        refuse("the output must be a spreadsheet (-o NAME.xlsx)");
    if (o.aov != Aov::color) refuse("the workbook computes the colour (--aov color)");
    for (const char* flag : {"--spp", "--exposure", "--tonemap", "--bit-depth", "--depth-cue",
                             "--wireframe-overlay", "--max-depth", "--light-samples", "--shadows"})
        if (render.count(flag) > 0)
            refuse(fmt::format("{} is not computed by the workbook's formulas", flag));
}

}  // namespace

CLI::App* add_render_command(CLI::App& app, RenderOptions& o) {
    CLI::App* render = app.add_subcommand("render", "Render a scene file to an image.");
    add_render_inputs(*render, o);
    add_size_options(*render, o);
    add_depth_options(*render, o);
    add_output_development_options(*render, o);
    add_set_option(*render, o.overrides);
    add_model_options(*render, o);
    add_extra_options(*render, o);
    add_frame_options(*render, o.frames);
    add_method_options(*render, o.own);
    render->footer(method_list());
    return render;
}

void check_render_command(const CLI::App& render, RenderOptions& o) {
    check_render_methods(render, o);
    if (!o.depth_cue.empty() && !(o.depth_cue[1] > o.depth_cue[0]))
        throw CLI::ValidationError("--depth-cue: FAR must be greater than NEAR");
    if (!o.depth_range.empty() && !(o.depth_range[1] > o.depth_range[0]))
        throw CLI::ValidationError("--depth-range: FAR must be greater than NEAR");
    if (o.wireframe_overlay && o.aov != Aov::color)
        throw CLI::ValidationError("--wireframe-overlay draws over the colour image (--aov color)");
    if (!o.depth_range.empty() && o.aov != Aov::depth)
        throw CLI::ValidationError("--depth-range is for --aov depth");
    check_output_development(render, o);
    check_formulas(render, o);
    check_frame_options(render, o);
}

}  // namespace hikari::cli
