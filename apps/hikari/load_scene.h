#pragma once
// The load step of `hikari render` (and `explain`): the scene or model the options name, edited
// as they ask, at the image size they ask for, within the memory limit.

#include <memory>

#include "hikari/scene/scene.h"
#include "hikari/session/session.h"
#include "render_options.h"

namespace hikari::cli {

/// The scene the options name (the built-in assignment when none), with --set, --camera-from,
/// --look-at, --crease-angle and --ground applied by the loader, then --width / --height,
/// --tessellation, a shading term's --aov and --depth-cue; its warnings printed on stderr.
/// Sets the --max-memory and --max-input-size limits first; throws InputError as loading does,
/// or when the image's buffers would not fit in the memory limit.
Scene load_render_scene(const RenderOptions& o);

/// The render session of the scene the options name (loaded with --set, --camera-from,
/// --look-at, --crease-angle and --ground), its load warnings printed on stderr; sets the limits
/// first. Image size and the other per-render edits are the requests' (render.cpp).
std::unique_ptr<Session> load_render_session(const RenderOptions& o);

/// What the options ask of every render: image size, AOV, method options, tessellation, depth
/// cue, wireframe overlay, threads (render.cpp adds the method, film and progress).
RenderRequest render_request(const RenderOptions& o);

}  // namespace hikari::cli
