#pragma once
// Scene files (JSON; docs/scene-format.md) into the plain-data Scene.

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hikari/io/scene_overrides.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// Builds a scene from JSON text. `file` names the text in error messages; relative mesh paths
/// are resolved against `base_dir`. Non-fatal problems (e.g. skipped degenerate mesh triangles)
/// are appended to `warnings`. `overrides` (`--set`) replace values of the parsed document
/// before the scene is built from it. Throws InputError with file and line:column or JSON path.
Scene parse_scene(std::string_view text, const std::string& file,
                  const std::filesystem::path& base_dir, std::vector<std::string>& warnings,
                  std::span<const SceneOverride> overrides = {});

/// Reads and parses a scene file.
Scene load_scene_file(const std::filesystem::path& path, std::vector<std::string>& warnings,
                      std::span<const SceneOverride> overrides = {});

/// The lecture's assignment, compiled into the program (scenes/assignment.json).
Scene load_default_scene(std::span<const SceneOverride> overrides = {});

}  // namespace hikari
