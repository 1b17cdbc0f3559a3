#pragma once
// Scenes far from the origin (issue 26, item 5), rebased while they are still JSON: every point
// the document gives is moved by −origin in double precision, before it is rounded to a 32-bit
// float. Rebasing the built Scene (scene/rebase.h) comes too late for coordinates such as
// 1000000.3, which no float holds; here they become 0.3 first.

#include <optional>

#include <nlohmann/json.hpp>

#include "hikari/scene/rebase.h"

namespace hikari {

/// When the document's camera is far from the origin (scene/rebase.h worth_rebasing: its eye's
/// largest coordinate is more than k_rebase_ratio · max(1, |look_at − eye|)), moves its points by
/// −origin, with origin the eye rounded to float (so that float points near it subtract
/// exactly): camera eye and look_at, point lights' positions, area lights' corners, spheres'
/// centres, planes' points, triangles' vertices, and the translation of every object's
/// transform (the last step's, when it is a translation; otherwise a translation step is
/// appended, and a mesh without a transform gets one). Returns the origin, or nullopt when the
/// camera is near the origin or the document is not well-formed enough to tell (the parser then
/// reports what is wrong, in the user's coordinates).
std::optional<WorldOrigin> rebase_scene_document(nlohmann::json& doc);

}  // namespace hikari
