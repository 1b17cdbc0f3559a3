#pragma once
// `--set PATH=VALUE`: a scene value replaced from the command line, by the JSON path that scene
// errors print (`materials.clay.shininess`, `objects[2].radius`, `camera.fov_y`). The override
// is applied to the parsed JSON document before the scene is built from it, so the value is
// checked exactly as if the file held it, and a bad one is reported at its path.

#include <span>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace hikari {

/// One `--set` argument.
struct SceneOverride {
    std::string argument;  ///< as given, "PATH=VALUE", for messages
    std::string path;      ///< "materials.clay.shininess", "objects[2].center"
    nlohmann::json value;  ///< VALUE as JSON; a bare word (clay) as the string "clay"
};

/// Parses "PATH=VALUE". VALUE is JSON (5, [0, 1, 0], true, "text", {"type": "sphere", ...}), or a
/// bare word of letters, digits, '_', '-' and '.' that starts with a letter, taken as a string.
/// Throws InputError naming the argument when it has no '=', an empty path, or a VALUE that is
/// neither.
SceneOverride parse_scene_override(std::string_view argument);

/// Sets each override's value in `doc`, in order. Path components are object keys, separated by
/// '.', and array indices, written [i] (or as a '.'-separated number). A missing key is added
/// (an object in between is created), so a value the file left at its default can be set; an
/// index must name an existing element. Throws InputError "--set ARG: PATH: reason" when the
/// path runs into a value of another kind or past an array's end.
void apply_scene_overrides(nlohmann::json& doc, std::span<const SceneOverride> overrides);

}  // namespace hikari
