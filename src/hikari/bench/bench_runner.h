#pragma once
// `hikari bench`: B1 and B2 of ../bench/SPEC.md timed the peers' way (N std::threads pulling
// chunks from an atomic counter, one warm-up pass and five timed passes, medians), printed as
// one JSON object.

#include <filesystem>
#include <string>
#include <vector>

#include "hikari/bench/bench_work.h"
#include "hikari/bvh/wide_bvh.h"
#include "hikari/core/simd_level.h"

namespace hikari {

/// Which benchmark and how.
struct BenchSettings {
    std::string bench = "B1";  ///< "B1" (closest hit, primary rays) or "B2" (occlusion rays)
    int threads = 1;           ///< worker threads for build and trace (>= 1)
    int repetitions = 5;       ///< timed passes (and timed builds) after one warm-up each
    SimdLevel simd = best_simd_level();  ///< kernel to run
    bool packets = false;  ///< B1 only: trace 4x4 pixel packets (intersect_closest_tile);
                           ///< reported as bench "B1p16"
};

/// Results of one benchmark run; times in milliseconds.
struct BenchResult {
    std::string bench;
    std::string mesh;  ///< the mesh file's stem ("bunny", "bumpy1m")
    int threads = 0;
    size_t triangles = 0;
    size_t rays = 0;
    std::vector<double> build_ms;  ///< one per timed build
    std::vector<double> trace_ms;  ///< one per timed pass
    size_t hits = 0;               ///< B1: rays that hit; B2: rays occluded
    double mean_t = 0;             ///< B1: mean distance over hits (double, pixel order)
    double bvh_bytes = 0;          ///< WideBvh::memory_bytes
    std::string simd;

    /// One JSON object: bench, mesh, threads, mrays_per_s (median; min/max too), build_ms
    /// (median), hits and mean_t (B1) or occluded and occluded_fraction (B2), and more.
    std::string to_json() const;
};

/// Closest hit of every ray (for B1 and for B2's ray generation): distance (or +inf) and
/// triangle per ray, on `threads` threads pulling chunks of `chunk` rays.
void trace_closest(const WideBvh& bvh, const BenchRays& rays, int threads, size_t chunk,
                   SimdLevel simd, std::vector<float>& hit_t, std::vector<uint32_t>& hit_triangle);

/// Closest hit of every ray of a `width`-wide row-major image of rays, as 4x4 packets
/// (intersect_closest_tile), on `threads` threads pulling chunks of `chunk_rows` rows (a multiple
/// of 4): distance (or +inf) and triangle per ray, as trace_closest gives them.
void trace_closest_packets(const WideBvh& bvh, const BenchRays& rays, uint32_t width, int threads,
                           uint32_t chunk_rows, SimdLevel simd, std::vector<float>& hit_t,
                           std::vector<uint32_t>& hit_triangle);

/// Any hit of every ray: 1 where occluded.
void trace_occluded(const WideBvh& bvh, const BenchRays& rays, int threads, size_t chunk,
                    SimdLevel simd, std::vector<uint8_t>& occluded);

/// Runs the benchmark on `mesh` (loaded by the caller; `mesh_name` goes into the result).
BenchResult run_bench(const BenchMesh& mesh, const std::string& mesh_name,
                      const BenchSettings& settings);

}  // namespace hikari
