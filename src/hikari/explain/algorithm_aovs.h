#pragma once
// Pictures of an algorithm at work (`--aov overdraw | paint-order | spans | culled`): what makes
// the Z-buffer, the depth sort and the scanline method differ although they draw the same image.
// Each runs the method's own code with an observer (raster/zbuffer.h, raster/scanline.h,
// raster/depth_sort.h DepthSortTrace). Which method has which is said by its registry entry
// (methods/registry.h, Method::algorithm_aovs), which names the function below that draws them.

#include <string>

#include "hikari/core/image.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/methods/registry.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// What an algorithm AOV image holds, and a line that says how to read it.
struct AlgorithmAov {
    Image image;
    std::string summary;  ///< e.g. "overdraw: 1.8 fragments per covered pixel, at most 6"
};

/// The algorithm AOV `aov` of `method` (has_algorithm_aov, methods/registry.h) for `scene`,
/// drawn by the method's own function (below):
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

/// The Z-buffer's (Alg 4.2): overdraw (fragments depth-tested per pixel) and culled.
AlgorithmAov zbuffer_algorithm_aov(const Scene& scene, const Method& method, Aov aov,
                                   const MethodSettings& own, bool raw);

/// The scanline method's (Alg 4.1): spans and culled.
AlgorithmAov scanline_algorithm_aov(const Scene& scene, const Method& method, Aov aov,
                                    const MethodSettings& own, bool raw);

/// The depth sort's (Fig 4.6-4.9): overdraw (polygons painted per pixel), paint-order and culled.
AlgorithmAov depth_sort_algorithm_aov(const Scene& scene, const Method& method, Aov aov,
                                      const MethodSettings& own, bool raw);

}  // namespace hikari
