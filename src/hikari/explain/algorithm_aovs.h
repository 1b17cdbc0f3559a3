#pragma once
// Pictures of an algorithm at work (`--aov overdraw | paint-order | spans | culled`): what makes
// the Z-buffer, the depth sort and the scanline method differ although they draw the same image.
// Each runs the method's own code with an observer (raster/zbuffer.h, raster/scanline.h,
// raster/depth_sort.h DepthSortTrace).

#include <string>
#include <string_view>

#include "hikari/core/image.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/methods/registry.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// Whether `method` has the algorithm AOV `aov`: overdraw (zbuffer: fragments depth-tested per
/// pixel; depthsort: polygons painted per pixel), paint-order (depthsort), spans (scanline),
/// culled (zbuffer, scanline, depthsort).
bool has_algorithm_aov(std::string_view method, Aov aov);

/// The methods that have `aov`, e.g. "zbuffer, depthsort".
std::string methods_with_algorithm_aov(Aov aov);

/// What an algorithm AOV image holds, and a line that says how to read it.
struct AlgorithmAov {
    Image image;
    std::string summary;  ///< e.g. "overdraw: 1.8 fragments per covered pixel, at most 6"
};

/// The algorithm AOV `aov` of `method` (has_algorithm_aov) for `scene`:
/// - overdraw: a ramp from dark blue (1) to white (the most), background black; `raw`: the count;
/// - paint-order: the painting position of the visible polygon, a ramp from dark blue (painted
///   first) to white (last), pieces of split polygons striped; `raw`: position + 1;
/// - spans: each visible triangle in a dim false colour, the first pixel of every sample span
///   (and of each piece a depth crossing splits off) white;
/// - culled: the method's colour image with every back face that culling drops overlaid half
///   in magenta (needs --cull back to drop any; then the image is as rendered).
/// Pictures are display values for 8-bit files (frame/aov_picture.h); `raw` (float files) keeps
/// the counts and positions as numbers.
AlgorithmAov algorithm_aov(const Scene& scene, const Method& method, Aov aov,
                           const MethodSettings& own, bool raw);

}  // namespace hikari
