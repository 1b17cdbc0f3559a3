#pragma once
// The registry of rendering methods: adding a method is one file and one entry in registry.cpp,
// which also lists the options the method understands.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hikari/frame/film.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/frame/line_drawing.h"
#include "hikari/frame/render_settings.h"
#include "hikari/methods/method_options.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// Renders a whole scene: every pixel of `film` (of the camera's size), returned with the AOVs.
/// Each method reads its own part of the MethodSettings.
using RenderFunction = Framebuffer (*)(const Scene& scene, Film film,
                                       const RenderSettings& settings, const MethodSettings& own);

/// Draws a whole scene as line segments (the line methods; what `-o drawing.svg` writes).
using DrawFunction = LineDrawing (*)(const Scene& scene, const MethodSettings& own);

/// What a method has to say about a scene before it renders it (one line per warning).
using SceneWarnings = std::vector<std::string> (*)(const Scene& scene);

/// A named rendering method selectable with `--method`.
struct Method {
    std::string_view name;                  ///< as given to --method
    std::string_view summary;               ///< one line for --help
    RenderFunction render;                  ///< the method itself
    std::span<const MethodOption> options;  ///< the method options it understands
    DrawFunction draw = nullptr;            ///< its segments, for the line methods; else null
    /// The `--shadows` modes it can do, its default first; empty when it draws no shadows.
    std::span<const ShadowMode> shadow_modes = {};
    /// Its warnings about a scene (e.g. materials it must change), or null for none.
    SceneWarnings warnings = nullptr;
    /// Whether its colour is the lecture's ambient + diffuse + specular (Fig 4.29, summed over
    /// the lights and the mirror and refracted rays), so that `--aov ambient|diffuse|specular`
    /// shows one term (shading/shading_terms.h).
    bool shading_terms = false;
};

/// Every registered method, the default (raytrace) first.
std::span<const Method> methods();

/// The method called `name`, or nullptr.
const Method* find_method(std::string_view name);

/// Renders `scene` with `method`, then the scene's post steps, which every method gets alike:
/// depth cueing (Fig 4.1b, frame/depth_cue.h). A depth cue needs linear colour and the depth
/// AOV, so with one the method renders into a linear film with the AOV buffers, whatever `film`
/// and `settings` ask, and the framebuffer returned holds linear colour. A render stopped
/// through settings.control is returned as it is. A scene far from the origin is first rebased
/// to its camera (scene/rebase.h), so it renders as it would at the origin.
Framebuffer render_scene(const Method& method, const Scene& scene, Film film,
                         RenderSettings settings, const MethodSettings& own);

/// The segments `method` draws for `scene` (method.draw must be set), depth-cued as the scene
/// asks (frame/line_drawing.h, depth_cued): what its image shows, as vectors. Rebased to the
/// camera as render_scene does.
LineDrawing draw_scene(const Method& method, const Scene& scene, const MethodSettings& own);

/// The methods whose colour is a sum of shading terms, e.g. "raytrace, zbuffer".
std::string shading_term_methods();

/// Whether `method` can draw shadows by `mode`.
bool does_shadows(const Method& method, ShadowMode mode);

/// The words of `method`'s shadow modes, e.g. "map, volume, none".
std::string shadow_mode_list(const Method& method);

/// Every option of any method, once each, in the order the methods list them.
std::vector<const MethodOption*> method_options();

/// Whether `method` understands the option called `flag` ("--spp").
bool takes_option(const Method& method, std::string_view flag);

}  // namespace hikari
