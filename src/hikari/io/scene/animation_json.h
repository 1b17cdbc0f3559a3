#pragma once
// A scene file's "animation" block (docs/scene-format.md) and the scene of one of its frames.
// Frame k is defined as a scene file: the document with the animation block taken out and the
// camera's, objects' and lights' values at frame k written in (an object's transform as steps
// appended to its own, a sphere's centre and radius, a light's position and direction), so a
// frame renders bit for bit as a still of that written-out file.

#include <string>

#include <nlohmann/json.hpp>

#include "hikari/scene/animation.h"

namespace hikari {

class JsonNode;  // io/scene/json_reader.h

/// The "animation" member of the scene document `root`, checked against the objects and lights
/// its keys name. Throws InputError naming the file and the JSON path of a bad value.
Animation parse_animation(const JsonNode& root);

/// The scene document of frame `frame` (0 to frame_count − 1) of `animation`, parsed from `doc`
/// (the scene document with its --set edits, before any rebasing). `file` names `doc` in
/// messages.
nlohmann::json frame_document(const nlohmann::json& doc, const Animation& animation, int frame,
                              const std::string& file);

}  // namespace hikari
