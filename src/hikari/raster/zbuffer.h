#pragma once
// The Z-buffer method (the lecture's Alg 4.2, Catmull 1974): every pixel keeps the depth of the
// nearest surface drawn so far, and a fragment is written only when it is nearer still.

#include <span>
#include <vector>

#include "hikari/core/simd_level.h"
#include "hikari/frame/film.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/frame/render_settings.h"
#include "hikari/raster/raster_settings.h"
#include "hikari/raster/screen_triangle.h"
#include "hikari/raster/sphere_raster.h"
#include "hikari/raster/tile_bins.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// Hidden-surface removal by Z-buffer: rasterizes `triangles` (half-space, top-left rule, pixel
/// centres) into a width × height visibility buffer. Z is the view depth 1 / inv_w interpolated
/// perspective-correctly, initialised to infinity; a fragment wins when z < Z, so on equal depth
/// the earlier triangle stays. Parallel over tiles, each with the triangles binned to it in
/// order: the result does not depend on the thread count. `control` may be null. `spheres`, when
/// given, are drawn exactly after the triangles of each tile (raster/sphere_raster.h); the
/// buffer then names them by the ids SphereRaster gives them.
VisibilityBuffer zbuffer_visibility(std::span<const ScreenTriangle> triangles, int width,
                                    int height, RenderControl* control = nullptr,
                                    const SphereRaster* spheres = nullptr);

/// What the Z-buffer keeps from one frame to the next: the triangles' setup and their tile bins.
/// Drawing frame after frame with one workspace allocates nothing once it has grown to size.
struct ZBufferWorkspace {
    std::vector<HalfSpaceTriangle> setup;
    std::vector<uint32_t> home;  ///< home_tile of each triangle (raster/tile_bins.h)
    TileBins bins;
};

/// zbuffer_visibility into buffers the caller owns: `nearest` (the ScreenTriangle seen at each
/// pixel) and `depth` (its depth 1 / inv_w, +infinity where none), width × height row-major;
/// either may be null (a depth-only pass). Edge functions and depth tests run `level`'s SIMD
/// kernel (raster/zbuffer_tile.h); every level gives the same buffers.
void zbuffer_draw(std::span<const ScreenTriangle> triangles, int width, int height,
                  ZBufferWorkspace& workspace, uint32_t* nearest, float* depth,
                  RenderControl* control = nullptr, SimdLevel level = best_simd_level());

/// zbuffer_draw over indexed triangles: the same buffers as drawing the ScreenTriangles they
/// stand for, without writing and reading those back (52 bytes a triangle).
void zbuffer_draw(const IndexedScreenTriangles& triangles, int width, int height,
                  ZBufferWorkspace& workspace, uint32_t* nearest, float* depth,
                  RenderControl* control = nullptr, SimdLevel level = best_simd_level());

/// One pass of Alg 4.2's inner loop at one pixel: a triangle's fragment, its depth, what the
/// Z-buffer held when it was tested, and whether the test let it replace that.
struct ZBufferFragment {
    uint32_t triangle = 0;  ///< index into the ScreenTriangle list
    float depth = 0;        ///< z = 1 / inv_w at the pixel centre
    float stored = 0;       ///< Z(i, j) before the test (infinity: nothing drawn yet)
    bool won = false;       ///< z < Z(i, j): written
};

/// zbuffer_visibility, also counting the fragments depth-tested at every pixel into
/// `fragments_per_pixel` (row-major): the overdraw (`--aov overdraw`, `--stats`). Exact spheres
/// are drawn but not counted.
VisibilityBuffer zbuffer_visibility_counted(std::span<const ScreenTriangle> triangles, int width,
                                            int height, std::vector<uint32_t>& fragments_per_pixel,
                                            const SphereRaster* spheres = nullptr);

/// zbuffer_visibility, also recording into `fragments` every fragment tested at pixel (x, y), in
/// the order the algorithm tested them (`hikari explain -m zbuffer --pixel X,Y`). The same code
/// runs: the render's loop reports each fragment to an observer that does nothing by default.
VisibilityBuffer zbuffer_visibility_at(std::span<const ScreenTriangle> triangles, int width,
                                       int height, int x, int y,
                                       std::vector<ZBufferFragment>& fragments);

/// The `zbuffer` method: vertex stage (raster/vertex_pipeline.h), zbuffer_visibility, then the
/// shared deferred shading pass (raster/shade_visibility.h). With per-pixel (Phong) shading,
/// spheres are drawn exactly (raster/sphere_raster.h); flat and Gouraud shading are defined on
/// polygons, so with them spheres are tessellated as for the other methods, and so are spheres
/// given a tessellation of their own (`segments`, `--tessellation`).
Framebuffer render_zbuffer(const Scene& scene, Film film, const RenderSettings& settings = {},
                           const RasterSettings& raster = {});

}  // namespace hikari
