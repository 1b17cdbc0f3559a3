#pragma once
// Model files of every supported format (OBJ, PLY, glTF), chosen by extension.

#include <filesystem>
#include <string_view>

#include "hikari/io/models/mesh_builder.h"

namespace hikari {

/// The extensions load_model() reads, for messages: ".obj, .ply, .gltf, .glb".
inline constexpr std::string_view k_model_extensions = ".obj, .ply, .gltf, .glb";

/// True when `path`'s extension (case-insensitive) names a model format load_model() reads.
bool is_model_file(const std::filesystem::path& path);

/// Loads the OBJ, PLY or glTF (.gltf or .glb) model at `path`. Throws InputError naming the file
/// for an unknown extension or anything the format's loader refuses.
MeshData load_model(const std::filesystem::path& path, const MeshOptions& options = {});

}  // namespace hikari
