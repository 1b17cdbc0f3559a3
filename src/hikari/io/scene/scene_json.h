#pragma once
// Scene files (JSON; docs/scene-format.md) into the plain-data Scene.

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hikari/io/models/mesh_data.h"
#include "hikari/io/scene/scene_overrides.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// What a scene load takes besides the text.
struct SceneLoadOptions {
    SceneLoadOptions() = default;
    /// Only command-line edits: as the span it extends, so the two convert alike.
    SceneLoadOptions(std::span<const SceneOverride> edits) : overrides(edits) {}  // NOLINT
    /// `--set`, applied to the document before anything is read from it.
    std::span<const SceneOverride> overrides;
    /// `--crease-angle`: every mesh's crease angle in degrees, over the file's "crease_angle".
    std::optional<float> crease_angle;
    /// A mesh already in memory (a model rendered as a scene, read once to frame it): the mesh
    /// object whose file is `preloaded_file` takes it instead of reading the file again.
    std::filesystem::path preloaded_file;
    const MeshData* preloaded = nullptr;
};

/// Builds a scene from JSON text. `file` names the text in error messages; relative mesh paths
/// are resolved against `base_dir`. Non-fatal problems (e.g. skipped degenerate mesh triangles)
/// are appended to `warnings`. `options.overrides` (`--set`) replace values of the parsed
/// document before the scene is built from it. Throws InputError with file and line:column or JSON
/// path.
Scene parse_scene(std::string_view text, const std::string& file,
                  const std::filesystem::path& base_dir, std::vector<std::string>& warnings,
                  const SceneLoadOptions& options = {});

/// parse_scene of a document already parsed, its `--set` edits applied (`options.overrides` is
/// not read): what an animation's frame (io/scene/animation_json.h) is built from.
Scene parse_scene_document(nlohmann::json doc, const std::string& file,
                           const std::filesystem::path& base_dir,
                           std::vector<std::string>& warnings,
                           const SceneLoadOptions& options = {});

class JsonNode;  // io/scene/json_reader.h

/// A scene file's "camera" object (docs/scene-format.md): what it leaves out takes the defaults.
/// Fails (InputError naming the JSON path) on unknown keys and on values no camera can have.
Camera parse_camera(const JsonNode& node);

/// Reads and parses a scene file.
Scene load_scene_file(const std::filesystem::path& path, std::vector<std::string>& warnings,
                      const SceneLoadOptions& options = {});

/// The lecture's assignment, compiled into the program (scenes/assignment.json).
Scene load_default_scene(const SceneLoadOptions& options = {});

}  // namespace hikari
