#pragma once
// What `hikari render` says on stderr once a method has rendered: the summary line and the
// `--stats` lines.

#include <string>

#include "hikari/frame/render_settings.h"
#include "hikari/methods/registry.h"
#include "hikari/scene/scene.h"

namespace hikari::cli {

/// Wall times of a render's phases, for the summary and `--stats`.
struct PhaseTimes {
    double load = 0;    ///< reading and checking the scene, in seconds
    double render = 0;  ///< the method's render (BVH build included)
    double write = 0;   ///< encoding and writing the output file
};

/// The line that ends a render: what was written, the scene's size and where the time went.
void print_summary(const std::string& output, int width, int height, const Method& method,
                   const Scene& scene, const PhaseTimes& times, const RenderStats& stats);

/// `--stats`: phase times, rays per second, the raster methods' vertex stage and hidden-surface
/// work (in the method's own words), and the BVH's figures.
void print_stats(const PhaseTimes& times, const RenderStats& stats, const Method& method);

}  // namespace hikari::cli
