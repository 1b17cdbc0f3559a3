#pragma once
// The repository's example scenes (scenes/), loaded at a test's image size.

#include <string>
#include <vector>

#include "hikari/io/scene/scene_json.h"

namespace hikari::testing {

/// Example scene `name` of scenes/ (e.g. "bunny.json") at a test's image size.
inline Scene scene_file(const std::string& name, int width, int height) {
    std::vector<std::string> warnings;
    Scene s = load_scene_file(std::string(HIKARI_SOURCE_DIR) + "/scenes/" + name, warnings);
    s.camera.width = width;
    s.camera.height = height;
    return s;
}

}  // namespace hikari::testing
