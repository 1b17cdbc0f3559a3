#pragma once
// Whitted ray tracing through the kernel entry point (core/device_launch.h): one HIKARI_HD body
// per pixel (whitted_kernel.h), run on the CPU's threads or, with `--device cuda`, as a grid on
// the GPU. The CPU run is what the test suite compares with render_whitted, so the GPU's code is
// covered without a GPU.

#include <string>

#include "hikari/core/cuda_devices.h"
#include "hikari/frame/film.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/frame/render_settings.h"
#include "hikari/integrators/whitted/whitted.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// What in `scene` or `whitted` the kernels cannot render yet (area and environment lights,
/// textures, vertex colours, analytic area shadows), as the message of a refusal; "" when
/// nothing.
std::string whitted_kernel_refusal(const Scene& scene, const WhittedSettings& whitted);

/// render_whitted's image from the kernels on `device`: every pixel's colour (the same as
/// render_whitted's up to rounding in the order the ray tree's colours are summed) and, with
/// settings.aov_buffers, the centre ray's depth, id and normal. InputError when the scene needs
/// what the kernels lack (whitted_kernel_refusal) or, on cuda, when no device can run them.
Framebuffer render_whitted_kernels(const Scene& scene, Film film, const RenderSettings& settings,
                                   const WhittedSettings& whitted, ExecutionDevice device);

}  // namespace hikari
