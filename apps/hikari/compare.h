#pragma once
// `hikari compare A B`: how far two images are apart.

#include <string>

#include <CLI/CLI.hpp>

namespace hikari::cli {

/// The options of `hikari compare`.
struct CompareOptions {
    std::string a, b;
    std::string output;  ///< the false-colour difference image; empty: none
    float tolerance = 0.0f;
    bool psnr_only = false;
};

/// `hikari compare` and its options.
CLI::App* add_compare_command(CLI::App& app, CompareOptions& c);

/// PSNR, the largest difference and the differing pixels of two images on stdout, and a
/// false-colour picture of where they differ (-o). Returns the exit status (0); throws
/// UsageError for an output that cannot be written, InputError for images that do not read or
/// do not match in size.
int run_compare(const CompareOptions& o);

}  // namespace hikari::cli
