#pragma once
// A session's scene written back out as a scene file with another camera: what `hikari serve`'s
// "download scene JSON" gives, so that `hikari render` of that file, from any folder, renders
// exactly the view on the screen.

#include <nlohmann/json.hpp>

#include "hikari/scene/camera.h"
#include "hikari/session/session.h"

namespace hikari {

/// The scene document (docs/scene-format.md) `source` loads: a scene file's own, the built-in
/// assignment's, or the one a model file becomes (io/models/model_scene.h); with its overrides
/// applied, its coordinates as the loader keeps them (moved near the origin when the scene lies
/// far from it), every "file" it names as an absolute path, a crease angle given to the loader
/// written on each mesh, and `camera` (with its image size) as its camera. Throws InputError as
/// loading `source` does.
nlohmann::json scene_document(const SceneSource& source, const Camera& camera);

/// `camera` as the scene format's "camera" object, every value exact (each float as the shortest
/// decimal that reads back as it).
nlohmann::json camera_document(const Camera& camera);

}  // namespace hikari
