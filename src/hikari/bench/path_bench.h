#pragma once
// `hikari bench B5`: the path tracer on the Cornell box of ../bench/SPEC.md §7, timed the way
// the SPEC times Cycles (one warm-up render at 4 samples per pixel, then timed renders in the
// same process, medians), printed as one JSON object.

#include <string>
#include <vector>

#include "hikari/core/vec.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// Settings of a B5 run.
struct PathBenchSettings {
    int threads = 1;             ///< worker threads (the caller limits the task arena)
    int repetitions = 3;         ///< timed renders after the warm-up
    int samples_per_pixel = 64;  ///< the SPEC's 64
    int max_depth = 8;           ///< the SPEC's 8 bounces
};

/// The results of a B5 run.
struct PathBenchResult {
    int threads = 0;
    int width = 0, height = 0;
    int samples_per_pixel = 0;
    std::vector<double> render_ms;  ///< wall time of each timed render
    Vec3 mean_srgb{0.0f};           ///< mean 8-bit sRGB pixel value / 255 of the last render

    /// One JSON object: bench, threads, ms (median), ms_all, mean_srgb, and the render's size.
    std::string to_json() const;
};

/// Renders `scene` with the path tracer as B5 asks.
PathBenchResult run_path_bench(const Scene& scene, const PathBenchSettings& settings);

}  // namespace hikari
