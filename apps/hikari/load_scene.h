#pragma once
// The load step of `hikari render` (and `explain`): the scene or model the options name, edited
// as they ask, at the image size they ask for, within the memory limit.

#include "hikari/scene/scene.h"
#include "render_options.h"

namespace hikari::cli {

/// The scene the options name (the built-in assignment when none), with --set, --camera-from,
/// --look-at, --crease-angle and --ground applied by the loader, then --width / --height,
/// --tessellation, a shading term's --aov and --depth-cue; its warnings printed on stderr.
/// Sets the --max-memory and --max-input-size limits first; throws InputError as loading does,
/// or when the image's buffers would not fit in the memory limit.
Scene load_render_scene(const RenderOptions& o);

}  // namespace hikari::cli
