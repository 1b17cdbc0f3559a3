#pragma once
// Parsing scene JSON text in tests, and reading the error a bad scene produces.

#include <string>
#include <vector>

#include "hikari/core/error.h"
#include "hikari/io/scene/scene_json.h"

namespace hikari::testing {

/// The scene in `json`, named "s.json" in errors, mesh paths relative to the working directory.
inline Scene parse(const std::string& json) {
    std::vector<std::string> warnings;
    return parse_scene(json, "s.json", ".", warnings);
}

/// The InputError message that parsing `json` produces ("" when it parses).
inline std::string error_of(const std::string& json) {
    try {
        parse(json);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace hikari::testing
