// The Whitted kernel's launch, apart from the rest of whitted_kernels.cpp: nvcc compiles this
// file (HIKARI_CUDA), and only what the kernel needs is included here (fmt, for one, does not
// compile under nvcc).
#include "hikari/core/device_launch.h"
#include "hikari/integrators/whitted/whitted_kernel.h"

namespace hikari {

void launch_whitted_kernel(ExecutionDevice device, size_t pixels,
                           const WhittedPixelKernel& kernel) {
    device_parallel_for(device, pixels, kernel, "raytrace kernels");
}

}  // namespace hikari
