#pragma once
// A render request and an explain step as JSON, for front ends that receive them as text
// (`hikari serve`'s API, docs/serve.md): the same names, ranges and messages as the command line.

#include <span>
#include <string_view>

#include <nlohmann/json.hpp>

#include "hikari/session/session.h"

namespace hikari {

/// {"method": "zbuffer", "width": 640, "height": 480, "aov": "color",
///  "camera": {"eye": [..], "look_at": [..], "up": [..], "fov_y": 45, "projection": ...},
///  "options": {"spp": 4, "shadows": "pcf", "line_color": [0.1, 0.1, 0.2]}}
/// Every key is optional (the scene's camera and size, the registry's first method, colour).
/// `extra_keys` are keys the caller reads itself (exposure, a pixel, ...). Throws InputError
/// "<what>: <JSON path>: <message>" for unknown keys and bad values.
RenderRequest render_request_from_json(const nlohmann::json& body, std::string_view what,
                                       std::span<const std::string_view> extra_keys = {});

/// The step of {"pixel": [x, y]} or {"row": y} (neither: the whole run).
ExplainStep explain_step_from_json(const nlohmann::json& body, std::string_view what);

}  // namespace hikari
