#pragma once

#include <string_view>

namespace hikari {

/// The text of scenes/assignment.json, compiled in: the scene `hikari render` draws when it is
/// given no scene file (the lecture's assignment: a Phong-shaded sphere).
std::string_view default_scene_json();

}  // namespace hikari
