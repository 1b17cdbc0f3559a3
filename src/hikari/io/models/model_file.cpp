#include "hikari/io/models/model_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <string>

#include "hikari/core/error.h"
#include "hikari/io/models/gltf_loader.h"
#include "hikari/io/models/obj_loader.h"
#include "hikari/io/models/ply_loader.h"

namespace hikari {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

}  // namespace

bool is_model_file(const std::filesystem::path& path) {
    const std::string ext = lower_extension(path);
    return ext == ".obj" || ext == ".ply" || ext == ".gltf" || ext == ".glb";
}

MeshData load_model(const std::filesystem::path& path, const MeshOptions& options) {
    const std::string ext = lower_extension(path);
    if (ext == ".obj") return load_obj(path, options);
    if (ext == ".ply") return load_ply(path, options);
    if (ext == ".gltf" || ext == ".glb") return load_gltf(path, options);
    throw InputError(
        fmt::format("{}: not a model file: expected one of {}", path.string(), k_model_extensions));
}

}  // namespace hikari
