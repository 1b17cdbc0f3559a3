#include "load_scene.h"

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "console.h"
#include "hikari/core/memory_budget.h"
#include "hikari/io/files/input_limits.h"
#include "hikari/io/models/model_file.h"
#include "hikari/io/models/model_scene.h"
#include "hikari/io/scene/scene_json.h"
#include "progress.h"

namespace hikari::cli {

namespace {

/// --max-memory and --max-input-size, for every stage that follows.
void set_limits(const RenderOptions& o) {
    if (o.max_memory_gib > 0) set_memory_limit(o.max_memory_gib * (1 << 30));
    if (o.max_input_gib > 0)
        set_max_input_size(static_cast<std::uintmax_t>(o.max_input_gib * (1 << 30)));
}

/// --set, then --camera-from and --look-at, which edit the document like --set (before a far
/// scene is rebased).
std::vector<SceneOverride> scene_edits(const RenderOptions& o) {
    std::vector<SceneOverride> overrides = o.overrides;
    if (!o.camera_from.empty()) overrides.push_back({"--camera-from", "camera.eye", o.camera_from});
    if (!o.look_at.empty()) overrides.push_back({"--look-at", "camera.look_at", o.look_at});
    return overrides;
}

/// The scene file, the model file framed as a scene, or the built-in assignment.
Scene read_scene(const RenderOptions& o, const SceneLoadOptions& load,
                 std::vector<std::string>& warnings) {
    ProgressReporter progress(!o.quiet, "loading " + o.scene_file, 0.0);
    if (o.scene_file.empty()) return load_default_scene(load);
    if (is_model_file(o.scene_file))
        return load_model_scene(o.scene_file, {.ground = o.ground, .mesh = {}}, warnings, load);
    return load_scene_file(o.scene_file, warnings, load);
}

/// Applies --width / --height; one alone keeps the camera's aspect ratio.
void resize_camera(Camera& camera, int width, int height) {
    if (width > 0 && height == 0)
        height = std::max(1, static_cast<int>(std::lround(static_cast<double>(width) *
                                                          camera.height / camera.width)));
    if (height > 0 && width == 0)
        width = std::max(1, static_cast<int>(std::lround(static_cast<double>(height) *
                                                         camera.width / camera.height)));
    if (width > 0) camera.width = width;
    if (height > 0) camera.height = height;
}

/// --tessellation, a shading term's --aov and --depth-cue, applied to the loaded scene.
Scene edit_scene(Scene scene, const RenderOptions& o) {
    if (o.tessellation > 0)
        for (Sphere& s : scene.spheres) s.segments = static_cast<uint32_t>(o.tessellation);
    if (const std::optional<ShadingTerm> term = shading_term_of(o.aov))
        scene = isolate_shading_term(std::move(scene), *term);
    if (!o.depth_cue.empty()) {
        // --depth-cue overrides the scene's distances and keeps its colour and blur.
        DepthCue cue = scene.depth_cue.value_or(DepthCue{});
        cue.near = o.depth_cue[0];
        cue.far = o.depth_cue[1];
        scene.depth_cue = cue;
    }
    return scene;
}

/// Refuses renders whose buffers would not fit in the memory limit, before allocating any.
void check_memory(const Camera& camera) {
    const double pixels = static_cast<double>(camera.width) * camera.height;
    // colour + depth + id + normal in the framebuffer, one more image for the output.
    check_memory_need(pixels * (sizeof(Vec3) * 3 + sizeof(float) + sizeof(uint32_t)),
                      fmt::format("a {}x{} image", camera.width, camera.height));
}

}  // namespace

Scene load_render_scene(const RenderOptions& o) {
    set_limits(o);
    const std::vector<SceneOverride> overrides = scene_edits(o);
    SceneLoadOptions load(overrides);
    if (o.crease_angle >= 0.0f) load.crease_angle = o.crease_angle;
    std::vector<std::string> warnings;
    Scene scene = read_scene(o, load, warnings);
    if (o.ground && !is_model_file(o.scene_file))
        warnings.emplace_back("--ground adds a plane under a model file; the scene has its own");
    for (const std::string& w : warnings) print_err("hikari: warning: {}\n", w);
    resize_camera(scene.camera, o.width, o.height);
    scene = edit_scene(std::move(scene), o);
    check_memory(scene.camera);
    return scene;
}

}  // namespace hikari::cli
