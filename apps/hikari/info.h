#pragma once
// `hikari info FILE`: what a model or scene file holds, and how long it took to load.

#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

namespace hikari {

/// The report `hikari info` prints for a model file (.obj, .ply, .gltf, .glb: triangles,
/// vertices, bounds, materials, textures, lights, cameras) or a scene file (the same for the
/// whole scene, plus its spheres and planes), with the load time. Throws InputError as loading
/// does.
std::string info_report(const std::filesystem::path& file);

/// The devices `--device` can name (`hikari info --devices`): the CPU's threads, and the CUDA
/// devices the runtime finds, or why there are none (no driver, no GPU, built without CUDA).
std::string devices_report();

namespace cli {

/// `hikari info FILE` and its argument, or `hikari info --devices`.
CLI::App* add_info_command(CLI::App& app, std::string& file, bool& devices);

/// Prints info_report(file) on stdout, or with `devices` the devices a render can run on
/// (devices_report); returns the exit status (0). UsageError without either.
int run_info(const std::string& file, bool devices);

}  // namespace cli

}  // namespace hikari
