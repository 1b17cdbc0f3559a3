#pragma once
// A model file rendered as a scene of its own (`hikari render bunny.ply`): the camera framed on
// the model, a default set of lights, and optionally a ground plane under it.

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hikari/io/models/mesh_builder.h"
#include "hikari/io/scene/scene_json.h"

namespace hikari {

/// How a model becomes a scene.
struct ModelSceneOptions {
    bool ground = false;  ///< --ground: a checkered plane just under the model's lowest point
    MeshOptions mesh;
};

/// The angles the default camera looks from: 30° to the right of the model's front (+z) and 20°
/// above it, up = +y (the convention of OBJ, PLY scans and glTF alike).
inline constexpr float k_model_view_azimuth_degrees = 30.0f;
inline constexpr float k_model_view_elevation_degrees = 20.0f;
/// The default camera's vertical field of view and image size.
inline constexpr float k_model_fov_y_degrees = 40.0f;
inline constexpr int k_model_image_width = 800;
inline constexpr int k_model_image_height = 600;

/// The scene document (docs/scene-format.md) that shows `mesh`, read from `file`: the mesh object
/// with the file's own materials (a neutral grey where it has none); the file's first camera, or
/// one that looks at the centre of the model's bounding sphere from the default direction and
/// far enough that the sphere just fills the view; the file's lights, or a key and a fill
/// directional light placed relative to that camera (upper left and right), plus ambient light.
nlohmann::json model_scene_document(const std::filesystem::path& file, const MeshData& mesh,
                                    const ModelSceneOptions& options);

/// Loads the model at `file` (io/model_file.h) once and builds the scene of
/// model_scene_document(), with `load.overrides` (--set) applied to that document. Throws
/// InputError as the loader and the scene parser do.
Scene load_model_scene(const std::filesystem::path& file, const ModelSceneOptions& options,
                       std::vector<std::string>& warnings, SceneLoadOptions load = {});

}  // namespace hikari
