#include "hikari/bench/path_bench.h"

#include <algorithm>
#include <chrono>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "hikari/bench/bench_work.h"
#include "hikari/methods/registry.h"

namespace hikari {

namespace {

/// One path-traced render of `scene` into an 8-bit film (what a PNG keeps), and its wall time.
Framebuffer render_once(const Scene& scene, int spp, int depth, double& ms) {
    MethodSettings own;
    own.samples_per_pixel = spp;
    own.max_depth = depth;
    RenderSettings settings;
    settings.aov_buffers = false;
    const auto start = std::chrono::steady_clock::now();
    Framebuffer fb = render_scene(*find_method("path"), scene,
                                  Film(scene.camera, FilmFormat::srgb8), settings, own);
    ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return fb;
}

}  // namespace

PathBenchResult run_path_bench(const Scene& scene, const PathBenchSettings& settings) {
    PathBenchResult result;
    result.threads = settings.threads;
    result.width = scene.camera.width;
    result.height = scene.camera.height;
    result.samples_per_pixel = settings.samples_per_pixel;
    double ms = 0.0;
    render_once(scene, 4, settings.max_depth, ms);  // warm-up
    Framebuffer last;
    for (int r = 0; r < settings.repetitions; ++r) {
        last = render_once(scene, settings.samples_per_pixel, settings.max_depth, ms);
        result.render_ms.push_back(ms);
    }
    const std::vector<uint8_t, UninitializedHugePageAllocator<uint8_t>>& bytes =
        last.film.srgb8().bytes;
    double sum[3] = {};
    for (size_t i = 0; i < bytes.size(); ++i) sum[i % 3] += bytes[i];
    const double pixels = static_cast<double>(bytes.size()) / 3.0;
    for (int a = 0; a < 3; ++a)
        result.mean_srgb[a] = static_cast<float>(sum[a] / (255.0 * std::max(1.0, pixels)));
    return result;
}

std::string PathBenchResult::to_json() const {
    return fmt::format(
        "{{\"bench\": \"B5\", \"threads\": {}, \"ms\": {:.1f}, \"ms_all\": [{:.1f}], "
        "\"mean_srgb\": [{:.4f}, {:.4f}, {:.4f}], \"width\": {}, \"height\": {}, \"spp\": {}}}",
        threads, median(render_ms), fmt::join(render_ms, ", "), mean_srgb.x, mean_srgb.y,
        mean_srgb.z, width, height, samples_per_pixel);
}

}  // namespace hikari
