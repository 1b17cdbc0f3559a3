#include "hikari/core/cuda_devices.h"
// No fmt here: its headers do not compile under nvcc, which builds this file with HIKARI_CUDA.

#include <cstdlib>
#include <new>
#include <string>

#include "hikari/core/error.h"

#if defined(HIKARI_CUDA)
#include <cuda_runtime.h>
#endif

namespace hikari {

CudaDevices find_cuda_devices() {
    CudaDevices found;
#if defined(HIKARI_CUDA)
    found.built = true;
    int count = 0;
    // Without a driver this says so (cudaErrorInsufficientDriver / cudaErrorNoDevice); the static
    // runtime opens libcuda itself, so the program starts either way.
    const cudaError_t status = cudaGetDeviceCount(&count);
    if (status != cudaSuccess) {
        found.problem = std::string("no CUDA device: ") + cudaGetErrorString(status) + " (" +
                        cudaGetErrorName(status) + ")";
        cudaGetLastError();  // clear it, so later calls do not report it again
        return found;
    }
    for (int d = 0; d < count; ++d) {
        cudaDeviceProp p{};
        if (cudaGetDeviceProperties(&p, d) != cudaSuccess) continue;
        found.devices.push_back(
            {p.name, p.major, p.minor, p.totalGlobalMem, p.multiProcessorCount});
    }
    if (found.devices.empty()) found.problem = "no CUDA device: the runtime found none";
#else
    found.problem = "no CUDA device: hikari was built without CUDA (HIKARI_CUDA=OFF or no nvcc)";
#endif
    return found;
}

void require_cuda_device(std::string_view what) {
    const CudaDevices found = find_cuda_devices();
    if (!found.problem.empty()) throw InputError(std::string(what) + ": " + found.problem);
}

void check_cuda(int status, std::string_view what) {
#if defined(HIKARI_CUDA)
    if (status == static_cast<int>(cudaSuccess)) return;
    const auto error = static_cast<cudaError_t>(status);
    throw InputError(std::string(what) + ": CUDA error: " + cudaGetErrorString(error) + " (" +
                     cudaGetErrorName(error) + ")");
#else
    if (status != 0) throw InputError(std::string(what) + ": CUDA error " + std::to_string(status));
#endif
}

void* DeviceArena::allocate(size_t bytes) {
    bytes = bytes == 0 ? 1 : bytes;
    void* memory = nullptr;
    if (m_device == ExecutionDevice::cuda) {
#if defined(HIKARI_CUDA)
        check_cuda(static_cast<int>(cudaMallocManaged(&memory, bytes)), "GPU memory");
#else
        throw InputError("GPU memory: hikari was built without CUDA");
#endif
    } else {
        memory = ::operator new (bytes, std::align_val_t{64});
    }
    m_blocks.push_back(memory);
    return memory;
}

DeviceArena::~DeviceArena() {
    for (void* block : m_blocks) {
#if defined(HIKARI_CUDA)
        if (m_device == ExecutionDevice::cuda) {
            cudaFree(block);
            continue;
        }
#endif
        ::operator delete (block, std::align_val_t{64});
    }
}

}  // namespace hikari
