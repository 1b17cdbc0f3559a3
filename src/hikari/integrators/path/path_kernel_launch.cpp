// The wavefront path tracer's launches, apart from the rest of path_kernels.cpp: nvcc compiles
// this file (HIKARI_CUDA), and only what the kernels need is included here (fmt, for one, does
// not compile under nvcc).
#include "hikari/core/device_launch.h"
#include "hikari/integrators/path/path_kernel.h"

namespace hikari {

void launch_path_kernel(ExecutionDevice device, size_t count, const GenerateCameraRays& kernel) {
    device_parallel_for(device, count, kernel, "path kernels: camera rays");
}

void launch_path_kernel(ExecutionDevice device, size_t count, const IntersectRays& kernel) {
    device_parallel_for(device, count, kernel, "path kernels: nearest hits");
}

void launch_path_kernel(ExecutionDevice device, size_t count, const ShadePaths& kernel) {
    device_parallel_for(device, count, kernel, "path kernels: shading");
}

void launch_path_kernel(ExecutionDevice device, size_t count, const TraceShadowRays& kernel) {
    device_parallel_for(device, count, kernel, "path kernels: shadow rays");
}

void launch_path_kernel(ExecutionDevice device, size_t count, const ResolvePixels& kernel) {
    device_parallel_for(device, count, kernel, "path kernels: pixel sums");
}

void launch_path_kernel(ExecutionDevice device, size_t count, const PixelCentreHits& kernel) {
    device_parallel_for(device, count, kernel, "path kernels: pixel-centre hits");
}

}  // namespace hikari
