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

namespace cli {

/// `hikari info FILE` and its argument.
CLI::App* add_info_command(CLI::App& app, std::string& file);

/// Prints info_report(file) on stdout; returns the exit status (0).
int run_info(const std::string& file);

}  // namespace cli

}  // namespace hikari
