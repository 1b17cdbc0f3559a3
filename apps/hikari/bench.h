#pragma once
// `hikari bench`: the peer benchmarks of bench/SPEC.md, one JSON object on stdout.

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "hikari/core/simd_level.h"

namespace hikari::cli {

/// The options of `hikari bench`.
struct BenchOptions {
    std::string bench;  ///< B1, B2, B4 or B5
    std::string mesh;
    std::string scene;  ///< B5; empty: the repository's scenes/bench/cornell.json
    std::optional<SimdLevel> simd;
    int threads = 1;
    std::optional<int> repetitions;  ///< default: 5 for B1 and B2, 3 for B5 (the SPEC's)
    bool packets = false;
    bool shadow = false;  ///< B4
    std::string output;   ///< B4: the last frame
};

/// `hikari bench` and its options.
CLI::App* add_bench_command(CLI::App& app, BenchOptions& b);

/// The usage error (CLI::ValidationError) of a parsed bench command line: B1, B2 and B4 need
/// --mesh.
void check_bench_command(const BenchOptions& b);

/// Runs the benchmark and prints its JSON object on stdout; returns the exit status (0).
/// Throws InputError for options of another benchmark, a mesh or scene that does not load.
int run_bench_command(const BenchOptions& o);

}  // namespace hikari::cli
