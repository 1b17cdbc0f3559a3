#pragma once
// The registry of rendering methods: adding a method is one file and one line in methods.cpp.

#include <span>
#include <string_view>

#include "hikari/frame/framebuffer.h"
#include "hikari/frame/render_settings.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// Renders a whole scene into a framebuffer of the camera's size.
using RenderFunction = Framebuffer (*)(const Scene&, const RenderSettings&);

/// A named rendering method selectable with `--method`.
struct Method {
    std::string_view name;
    std::string_view summary;  ///< one line for --help
    RenderFunction render;
};

/// Every registered method, the default (raytrace) first.
std::span<const Method> methods();

/// The method called `name`, or nullptr.
const Method* find_method(std::string_view name);

}  // namespace hikari
