#pragma once
// `hikari info FILE`: what a model or scene file holds, and how long it took to load.

#include <filesystem>
#include <string>

namespace hikari {

/// The report `hikari info` prints for a model file (.obj, .ply, .gltf, .glb: triangles,
/// vertices, bounds, materials, textures, lights, cameras) or a scene file (the same for the
/// whole scene, plus its spheres and planes), with the load time. Throws InputError as loading
/// does.
std::string info_report(const std::filesystem::path& file);

}  // namespace hikari
