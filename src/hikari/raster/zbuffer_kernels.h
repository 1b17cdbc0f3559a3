#pragma once
// The Z-buffer through the kernel entry point (core/device_launch.h): the vertex stage, triangle
// setup, tile binning, the per-pixel depth test and deferred shading as HIKARI_HD
// kernels (zbuffer_kernel.h), run on the CPU's threads or, with `--device cuda`, as grids on the
// GPU. The CPU run is what the test suite compares with render_zbuffer, so the GPU's code is
// covered without a GPU.

#include <span>
#include <string>
#include <vector>

#include "hikari/core/cuda_devices.h"
#include "hikari/frame/film.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/frame/render_settings.h"
#include "hikari/raster/raster_settings.h"
#include "hikari/raster/screen_triangle.h"
#include "hikari/raster/vertex_pipeline.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// What in `scene` or `raster` the Z-buffer kernels cannot render yet (area and environment
/// lights, image textures, shadow volumes, PCSS and analytic shadows), as the message of a
/// refusal; "" when nothing.
std::string zbuffer_kernel_refusal(const Scene& scene, const RasterSettings& raster);

/// project_scene(scene, raster, exact spheres under Phong shading) through the kernels on `device`:
/// each vertex transformed and each triangle culled or kept whole by a kernel, the few that cross
/// the near plane or the guard band clipped on the host; the same screen triangles, clip positions
/// and counts.
ProjectedScene project_scene_with_kernels(const Scene& scene, const RasterSettings& raster,
                                          ExecutionDevice device);

/// zbuffer_draw's buffers (raster/zbuffer.h) from the kernels on `device`: `nearest` (the
/// screen triangle seen at each pixel, k_no_triangle for none) and `depth` (1 / inv_w, +infinity
/// for none), width × height row-major, either may be null.
void zbuffer_kernels_draw(std::span<const ScreenTriangle> triangles, int width, int height,
                          uint32_t* nearest, float* depth, ExecutionDevice device);

/// render_zbuffer's image from the kernels on `device`: the same ids and depths, colours equal
/// up to rounding, the same AOVs. InputError when the scene needs what the kernels lack
/// (zbuffer_kernel_refusal) or, on cuda, when no device can run them; nothing is uploaded then.
Framebuffer render_zbuffer_kernels(const Scene& scene, Film film, const RenderSettings& settings,
                                   const RasterSettings& raster, ExecutionDevice device);

}  // namespace hikari
