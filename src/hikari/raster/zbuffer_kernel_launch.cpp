// The Z-buffer kernels' launches, apart from the rest of zbuffer_kernels.cpp: nvcc compiles this
// file (HIKARI_CUDA), and only what the kernels need is included here (fmt, for one, does not
// compile under nvcc).
#include "hikari/core/device_launch.h"
#include "hikari/raster/zbuffer_kernel.h"

namespace hikari {

void launch_zbuffer_kernel(ExecutionDevice device, size_t count, const VertexKernel& k) {
    device_parallel_for(device, count, k, "zbuffer kernels (vertices)");
}
void launch_zbuffer_kernel(ExecutionDevice device, size_t count, const TriangleFateKernel& k) {
    device_parallel_for(device, count, k, "zbuffer kernels (culling)");
}
void launch_zbuffer_kernel(ExecutionDevice device, size_t count, const TriangleAssembleKernel& k) {
    device_parallel_for(device, count, k, "zbuffer kernels (screen triangles)");
}
void launch_zbuffer_kernel(ExecutionDevice device, size_t count, const TriangleSetupKernel& k) {
    device_parallel_for(device, count, k, "zbuffer kernels (triangle setup)");
}
void launch_zbuffer_kernel(ExecutionDevice device, size_t count, const BinCountKernel& k) {
    device_parallel_for(device, count, k, "zbuffer kernels (bin counts)");
}
void launch_zbuffer_kernel(ExecutionDevice device, size_t count, const BinTotalKernel& k) {
    device_parallel_for(device, count, k, "zbuffer kernels (bin totals)");
}
void launch_zbuffer_kernel(ExecutionDevice device, size_t count, const BinFillKernel& k) {
    device_parallel_for(device, count, k, "zbuffer kernels (bin fill)");
}
void launch_zbuffer_kernel(ExecutionDevice device, size_t count, const ZBufferPixelKernel& k) {
    device_parallel_for(device, count, k, "zbuffer kernels (depth test)");
}
void launch_zbuffer_kernel(ExecutionDevice device, size_t count, const ZBufferShadeKernel& k) {
    device_parallel_for(device, count, k, "zbuffer kernels (shading)");
}

}  // namespace hikari
