#pragma once
// `hikari bench B4`: the rasterization benchmark of ../bench/SPEC.md §6, the frame llvmpipe draws
// through OSMesa, done by the path `hikari render -m zbuffer` takes: the SPEC's mesh, material,
// light and B1 camera at 1920 × 1080 as a scene, rendered by the `zbuffer` method (vertex stage,
// binned SIMD Z-buffer with no culling, deferred Phong shading in lanes), and with `shadow` its
// 2048² shadow map drawn before every frame. The linear colours are then gamma-encoded to the
// 8-bit frame llvmpipe's fragment shader writes.

#include <cstdint>
#include <string>
#include <vector>

#include "hikari/bench/bench_work.h"
#include "hikari/core/image.h"
#include "hikari/core/simd_level.h"

namespace hikari {

/// How B4 runs.
struct RasterBenchSettings {
    int threads = 1;        ///< worker threads (the caller limits the task arena)
    bool shadow = false;    ///< the shadow-map variant
    int warmup_frames = 3;  ///< the SPEC's 3
    int timed_frames = 20;  ///< the SPEC's 20
    int width = 1920, height = 1080;
    int shadow_map_size = 2048;
    SimdLevel simd = best_simd_level();  ///< the Z-buffer's and the shading lanes' kernels
};

/// What a B4 run measured.
struct RasterBenchResult {
    std::string mesh;
    int threads = 0;
    bool shadow = false;
    size_t triangles = 0;
    std::vector<double> frame_ms;  ///< each timed frame
    size_t covered_pixels = 0;     ///< pixels of the last frame that differ from the clear colour
    size_t shadowed_pixels = 0;    ///< covered pixels the shadow map darkened (shadow variant)
    std::string simd;

    /// One JSON object: bench, mesh, threads, variant, ms_per_frame (median), ms_min, ms_max,
    /// ms_all, covered_pixels, and more.
    std::string to_json() const;
};

/// Draws `settings.warmup_frames` + `settings.timed_frames` B4 frames of `mesh` (loaded once,
/// as llvmpipe's vertex buffer is) and times the timed ones. The last frame is left in `image`
/// when given (row 0 at the top, sRGB bytes as glReadPixels would give them, flipped).
RasterBenchResult run_raster_bench(const BenchMesh& mesh, const std::string& mesh_name,
                                   const RasterBenchSettings& settings,
                                   Srgb8Image* image = nullptr);

}  // namespace hikari
