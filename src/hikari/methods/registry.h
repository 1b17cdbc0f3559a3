#pragma once
// The registry of rendering methods: adding a method is one file and one entry in registry.cpp.
// The entry says all the method offers — its options, shadow modes, algorithm AOVs, `explain`
// views, `--stats` words, SVG drawing — so that no code outside the registry compares a
// method's name (tests/methods/method_names_test.cpp holds it).

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

/// What a method can print of its work for `hikari explain -m METHOD` (explain/explain.h), one
/// view per way of choosing the step; null where it has none.
struct ExplainViews {
    /// One pixel's story, for `--pixel X,Y` (the Z-buffer's fragments, the ray tracer's ray tree).
    std::string (*pixel)(const Scene& scene, const MethodSettings& own, int x, int y) = nullptr;
    /// One scan line's, for `--row Y` (the scanline method's edge table, active edges, spans).
    std::string (*row)(const Scene& scene, const MethodSettings& own, int row) = nullptr;
    /// The whole scene's at once (the depth sort's comparisons and painting order).
    std::string (*whole)(const Scene& scene, const MethodSettings& own) = nullptr;
};

struct AlgorithmAov;  // explain/algorithm_aovs.h
struct Method;

/// The pictures of a method's algorithm at work (`--aov overdraw | paint-order | spans |
/// culled`, explain/algorithm_aovs.h).
struct AlgorithmAovs {
    std::span<const Aov> aovs;  ///< the ones it has; empty: none
    /// Draws one of `aovs` for a scene (`raw`: the counts as numbers, for float files).
    AlgorithmAov (*draw)(const Scene& scene, const Method& method, Aov aov,
                         const MethodSettings& own, bool raw) = nullptr;
};

/// What `--stats` says of a raster method's hidden-surface work.
struct StatsWords {
    /// What RenderStats::raster_fragments counts for it, e.g. "sample spans".
    std::string_view work = {};
    /// Whether it splits polygons (the depth sort): the split count is printed even when 0.
    bool splits = false;
};

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
    /// Its algorithm AOVs.
    AlgorithmAovs algorithm_aovs = {};
    /// Its `hikari explain` views.
    ExplainViews explain = {};
    /// Its `--stats` words.
    StatsWords stats = {};
    /// The usage error of an option value it cannot take (e.g. `--max-depth 0` for a method
    /// that needs the camera ray), or empty; null: it takes every value the options allow.
    std::string (*refuse_values)(const MethodSettings& own) = nullptr;
    /// Whether processes can share one image (frame/tile_share.h): every pixel it writes comes
    /// from the camera's tile loop (frame/tiles.h) or from a pass each process runs whole (the
    /// AOVs, the caustic light paths), so tiles rendered apart and gathered are one image.
    bool shares_tiles = false;
};

/// Every registered method, the default (raytrace) first.
std::span<const Method> methods();

/// The method called `name`, or nullptr.
const Method* find_method(std::string_view name);

/// Renders `scene` with `method`, then the scene's post steps, which every method gets alike:
/// depth cueing (Fig 4.1b, frame/depth_cue.h). A depth cue needs linear colour and the depth
/// AOV, so with one the method renders into a linear film with the AOV buffers, whatever `film`
/// and `settings` ask, and the framebuffer returned holds linear colour. A render stopped
/// through settings.control is returned as it is. With a tile share in settings.control (only
/// for a method that shares_tiles), the share's combine runs after the method, before the post
/// steps. A scene far from the origin is first rebased
/// to its camera (scene/rebase.h), so it renders as it would at the origin.
Framebuffer render_scene(const Method& method, const Scene& scene, Film film,
                         RenderSettings settings, const MethodSettings& own);

/// The segments `method` draws for `scene` (method.draw must be set), depth-cued as the scene
/// asks (frame/line_drawing.h, depth_cued): what its image shows, as vectors. Rebased to the
/// camera as render_scene does.
LineDrawing draw_scene(const Method& method, const Scene& scene, const MethodSettings& own);

/// The methods whose colour is a sum of shading terms, e.g. "raytrace, zbuffer".
std::string shading_term_methods();

/// The methods that draw lines as segments (method.draw set), e.g. "wireframe, hiddenline".
std::string drawing_methods();

/// Whether `method` has the algorithm AOV `aov`.
bool has_algorithm_aov(const Method& method, Aov aov);

/// The methods that have the algorithm AOV `aov`, e.g. "zbuffer, depthsort".
std::string methods_with_algorithm_aov(Aov aov);

/// Whether `method` has any `hikari explain` view.
bool has_explain_view(const Method& method);

/// Whether `method` can draw shadows by `mode`.
bool does_shadows(const Method& method, ShadowMode mode);

/// The words of `method`'s shadow modes, e.g. "map, volume, none".
std::string shadow_mode_list(const Method& method);

/// Every option of any method, once each, in the order the methods list them.
std::vector<const MethodOption*> method_options();

/// Whether `method` understands the option called `flag` ("--spp").
bool takes_option(const Method& method, std::string_view flag);

}  // namespace hikari
