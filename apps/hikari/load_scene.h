#pragma once
// The load step of `hikari render` (and `explain`): the scene or model the options name, edited
// as they ask, at the image size they ask for, within the memory limit.

#include <memory>

#include "hikari/session/session.h"
#include "render_options.h"

namespace hikari::cli {

/// What the options name to load: the scene file, the model file framed as a scene, or the
/// built-in assignment, with --set, --camera-from, --look-at, --crease-angle and --ground.
SceneSource scene_source(const RenderOptions& o);

/// The render session of the scene the options name (the built-in assignment when none; loaded
/// with --set, --camera-from, --look-at, --crease-angle and --ground), its load warnings printed
/// on stderr; sets the --max-memory and --max-input-size limits first. Image size and the other
/// per-render edits are the requests' (render.cpp).
std::unique_ptr<Session> load_render_session(const RenderOptions& o);

/// What the options ask of every render: image size, AOV, method options, tessellation, depth
/// cue, wireframe overlay, threads (render.cpp adds the method, film and progress).
RenderRequest render_request(const RenderOptions& o);

}  // namespace hikari::cli
