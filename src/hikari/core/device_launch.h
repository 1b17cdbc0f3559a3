#pragma once
// One entry point for every kernel (issue 46): `device_parallel_for(device, n, kernel)` calls
// kernel(i) for each i in [0, n), as a grid of GPU threads when `device` is cuda (the file that
// calls it compiled by nvcc, HIKARI_CUDA), on the CPU's threads (core/parallel.h) otherwise. The
// kernel is a small struct of flat views (core/flat_view.h) whose `operator()(size_t) const` is
// HIKARI_HD, so the body written once runs on both, and the CPU test suite covers the GPU's code.

#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "hikari/core/cuda_devices.h"
#include "hikari/core/host_device.h"
#include "hikari/core/parallel.h"

namespace hikari {

#if defined(__CUDACC__)
/// One GPU thread per index; the last block's threads past `count` do nothing.
template <class Kernel>
__global__ void device_grid(size_t count, Kernel kernel) {
    const size_t i = static_cast<size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
    if (i < count) kernel(i);
}
#endif

/// Threads per block of a device grid: a multiple of the warp, small enough that the kernels'
/// local stacks (BVH and ray-tree stacks, a few KiB per thread) leave room for several blocks.
inline constexpr unsigned k_device_block = 128;

/// kernel(i) for every i in [0, count) on `device`, returning when all are done. CUDA errors
/// (launch, execution) are thrown as InputError naming the kernel.
template <class Kernel>
void device_parallel_for(ExecutionDevice device, size_t count, const Kernel& kernel,
                         const char* name) {
    if (count == 0) return;
    if (device == ExecutionDevice::cuda) {
#if defined(__CUDACC__)
        const size_t blocks = (count + k_device_block - 1) / k_device_block;
        device_grid<<<static_cast<unsigned>(blocks), k_device_block>>>(count, kernel);
        check_cuda(static_cast<int>(cudaGetLastError()), name);
        check_cuda(static_cast<int>(cudaDeviceSynchronize()), name);
        return;
#else
        throw std::logic_error(std::string(name) +
                               ": a CUDA launch from a file nvcc did not compile");
#endif
    }
    parallel_for(size_t{0}, count, [&](size_t i) { kernel(i); });
}

}  // namespace hikari
