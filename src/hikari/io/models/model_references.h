#pragma once
// The files a model file names, found without loading it: an OBJ's MTL libraries and the
// textures they name, a glTF's external images and buffers. A front end protects them as it
// protects the model itself (a render never overwrites a file it reads), before any work.

#include <filesystem>
#include <vector>

namespace hikari {

/// The files `model` names (paths as the loaders resolve them: an MTL library relative to its
/// OBJ, a texture relative to its MTL library, a glTF URI relative to the glTF file). Reads
/// only what it needs: the OBJ's `mtllib` lines in fixed-size blocks, MTL files and a glTF's
/// JSON up to 64 MiB; a file that cannot be read or parsed names nothing here (its loader
/// reports it). Other formats name no files.
std::vector<std::filesystem::path> model_references(const std::filesystem::path& model);

}  // namespace hikari
