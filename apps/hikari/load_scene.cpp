#include "load_scene.h"

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <tbb/global_control.h>

#include "console.h"
#include "hikari/core/memory_budget.h"
#include "hikari/io/files/input_limits.h"
#include "hikari/session/session.h"
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

/// Prints what loading had to say.
void print_warnings(const std::vector<std::string>& warnings) {
    for (const std::string& w : warnings) print_err("hikari: warning: {}\n", w);
}

}  // namespace

SceneSource scene_source(const RenderOptions& o) {
    SceneSource source;
    source.file = o.scene_file;
    source.overrides = scene_edits(o);
    source.ground = o.ground;
    if (o.crease_angle >= 0.0f) source.crease_angle = o.crease_angle;
    return source;
}

RenderRequest render_request(const RenderOptions& o) {
    RenderRequest request;
    request.width = o.width;
    request.height = o.height;
    request.aov = o.aov;
    request.options = o.own;
    request.tessellation = o.tessellation;
    if (!o.depth_cue.empty()) request.depth_cue = std::pair(o.depth_cue[0], o.depth_cue[1]);
    request.wireframe_overlay = o.wireframe_overlay;
    request.threads = o.threads;
    return request;
}

std::unique_ptr<Session> load_render_session(const RenderOptions& o) {
    set_limits(o);
    std::unique_ptr<Session> session;
    {
        // --threads holds for loading too (the parsers and the mesh builder run in parallel)
        std::optional<tbb::global_control> thread_limit;
        if (o.threads > 0)
            thread_limit.emplace(tbb::global_control::max_allowed_parallelism,
                                 static_cast<size_t>(o.threads));
        ProgressReporter progress(!o.quiet, "loading " + o.scene_file, 0.0);
        session = std::make_unique<Session>(scene_source(o));
    }
    print_warnings(session->load_warnings());
    return session;
}

}  // namespace hikari::cli
