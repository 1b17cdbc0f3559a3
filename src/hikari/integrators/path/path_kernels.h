#pragma once
// Path tracing through the kernel entry point (core/device_launch.h) as a wavefront integrator
// (path_kernel.h): ray generation, nearest hits, shading and shadow rays as kernels over queues,
// run on the CPU's threads or, with `--device cuda`, as grids on the GPU. The CPU run is what the
// test suite compares with render_path, so the GPU's code is covered without a GPU.

#include <string>

#include "hikari/core/cuda_devices.h"
#include "hikari/frame/film.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/frame/render_settings.h"
#include "hikari/integrators/path/path_tracer.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// What in `scene` or `path` the kernels cannot render yet (environment maps, image textures,
/// --time-limit, --progressive), as the message of a refusal; "" when nothing.
std::string path_kernel_refusal(const Scene& scene, const PathSettings& path);

/// render_path's image from the kernels on `device`: the same samples of the same Sobol'
/// sequences, the same estimator, each pixel's samples summed in the same order, so on the CPU
/// the same pixels as render_path with light_traced_caustics false (caustics are left to the
/// camera paths here, whatever `path` says); with settings.aov_buffers, the centre ray's depth,
/// id and normal. The image is the same for any thread count. InputError when the scene or the
/// settings need what the kernels lack (path_kernel_refusal) or, on cuda, when no device can
/// run them; nothing is uploaded before.
Framebuffer render_path_kernels(const Scene& scene, Film film, const RenderSettings& settings,
                                const PathSettings& path, ExecutionDevice device);

}  // namespace hikari
