#include "bench.h"

#include <filesystem>
#include <vector>

#include <fmt/format.h>
#include <tbb/global_control.h>

#include "cli_options.h"
#include "console.h"
#include "data_folder.h"
#include "hikari/bench/bench_runner.h"
#include "hikari/bench/path_bench.h"
#include "hikari/bench/raster_bench.h"
#include "hikari/core/error.h"
#include "hikari/io/images/image_format.h"
#include "hikari/io/images/image_write.h"
#include "hikari/io/scene/scene_json.h"

namespace hikari::cli {

namespace {

/// `--simd`'s words; auto (nullopt) is the best level this CPU has.
constexpr Choice<std::optional<SimdLevel>> k_simd_choices[] = {{"auto", std::nullopt},
                                                               {"portable", SimdLevel::portable},
                                                               {"avx2", SimdLevel::avx2},
                                                               {"avx512", SimdLevel::avx512}};

/// `hikari bench B5`: the path tracer on the Cornell box (SPEC §7), one JSON object on stdout.
int run_path_bench_command(const BenchOptions& o) {
    if (!o.mesh.empty() || o.packets || o.simd || o.shadow || !o.output.empty())
        throw InputError(
            "B5 renders a scene: --mesh, --packets, --simd, --shadow and --output are for B1, B2 "
            "and B4");
    const std::string file =
        o.scene.empty() ? (data_folder() / "scenes" / "bench" / "cornell.json").string() : o.scene;
    std::vector<std::string> warnings;
    const Scene scene = load_scene_file(file, warnings);
    for (const std::string& w : warnings) print_err("hikari: warning: {}\n", w);
    const tbb::global_control thread_limit(tbb::global_control::max_allowed_parallelism,
                                           static_cast<size_t>(o.threads));
    PathBenchSettings settings;
    settings.threads = o.threads;
    settings.repetitions = o.repetitions.value_or(settings.repetitions);
    print_out("{}\n", run_path_bench(scene, settings).to_json());
    return 0;
}

/// The kernel `--simd` asks for, or `fallback` (the best this CPU has) for auto; an error when
/// this CPU cannot run the one asked for.
SimdLevel chosen_simd(std::optional<SimdLevel> asked, SimdLevel fallback) {
    if (!asked) return fallback;
    if (!simd_level_supported(*asked))
        throw InputError(fmt::format("this CPU cannot run --simd {}", simd_level_name(*asked)));
    return *asked;
}

/// `hikari bench B4`: the raster frame of SPEC §6, one JSON object on stdout.
int run_raster_bench_command(const BenchOptions& o) {
    if (o.packets || !o.scene.empty())
        throw InputError("B4 draws a mesh: --packets and --scene are for B1 and B5");
    if (!o.output.empty() && !is_supported_image_extension(o.output))
        throw InputError(fmt::format("{}: unsupported output format (use {})", o.output,
                                     k_writable_image_extensions));
    RasterBenchSettings settings;
    settings.threads = o.threads;
    settings.shadow = o.shadow;
    settings.timed_frames = o.repetitions.value_or(settings.timed_frames);
    settings.simd = chosen_simd(o.simd, settings.simd);
    const BenchMesh mesh = load_bench_mesh(o.mesh);
    const tbb::global_control thread_limit(tbb::global_control::max_allowed_parallelism,
                                           static_cast<size_t>(o.threads));
    Srgb8Image image;
    const RasterBenchResult result =
        run_raster_bench(mesh, std::filesystem::path(o.mesh).stem().string(), settings, &image);
    if (!o.output.empty()) write_image(o.output, image);
    print_out("{}\n", result.to_json());
    return 0;
}

}  // namespace

CLI::App* add_bench_command(CLI::App& app, BenchOptions& b) {
    CLI::App* bench = app.add_subcommand(
        "bench", "Run a peer benchmark (bench/SPEC.md) and print one JSON object on stdout.");
    bench
        ->add_option("name", b.bench,
                     "B1 (primary rays, closest hit), B2 (occlusion rays), B4 (rasterized "
                     "1920x1080 Phong frame, as llvmpipe draws it) or B5 (path-traced Cornell "
                     "box, 64 spp, 8 bounces)")
        ->required()
        ->check(CLI::IsMember({"B1", "B2", "B4", "B5"}));
    // No CLI::ExistingFile: a missing or unreadable mesh is an input error (exit 1), as for
    // a render's scene file, reported by the loader.
    bench->add_option("--mesh", b.mesh, "B1, B2, B4: OBJ mesh (positions and faces are read)");
    bench->add_option("--scene", b.scene,
                      "B5: scene file (default: the repository's scenes/bench/cornell.json)");
    bench->add_option("--threads", b.threads, "Threads for build and trace")
        ->check(whole_in(1, 1024))
        ->capture_default_str();
    bench
        ->add_option("--reps", b.repetitions,
                     "Timed repetitions after the warm-up (default: 5; B4: 20 frames after 3; "
                     "B5: 3)")
        ->check(whole_in(1, 1000));
    add_choice_option<std::optional<SimdLevel>>(
        *bench, "--simd", "Traversal kernel: auto (best), portable, avx2, avx512", k_simd_choices,
        b.simd);
    bench->add_flag("--packets", b.packets,
                    "B1 as 4x4 pixel packets (coherent packet traversal); reported as B1p16");
    bench->add_flag("--shadow", b.shadow,
                    "B4 with the 2048x2048 shadow-map pass before every frame");
    bench->add_option("-o,--output", b.output,
                      "B4: write the last frame (PNG, PPM, ...), to compare with llvmpipe's");
    return bench;
}

void check_bench_command(const BenchOptions& b) {
    if (b.bench != "B5" && b.mesh.empty())
        throw CLI::ValidationError(fmt::format("{} needs --mesh FILE (an OBJ mesh)", b.bench));
}

int run_bench_command(const BenchOptions& o) {
    if (o.bench == "B5") return run_path_bench_command(o);
    if (o.bench == "B4") return run_raster_bench_command(o);
    if (o.shadow || !o.output.empty()) throw InputError("--shadow and --output are for B4");
    if (!o.scene.empty()) throw InputError("--scene is for B5");
    BenchSettings settings;
    settings.bench = o.bench;
    settings.threads = o.threads;
    settings.repetitions = o.repetitions.value_or(settings.repetitions);
    settings.packets = o.packets;
    if (o.packets && o.bench != "B1") throw InputError("--packets is for B1 only");
    settings.simd = chosen_simd(o.simd, settings.simd);
    const BenchMesh mesh = load_bench_mesh(o.mesh);
    const BenchResult result =
        run_bench(mesh, std::filesystem::path(o.mesh).stem().string(), settings);
    print_out("{}\n", result.to_json());
    return 0;
}

}  // namespace hikari::cli
