#pragma once
// The CUDA devices this process can use (`hikari info --devices`, `--device cuda`) and the GPU
// memory the kernels read. Built without CUDA (HIKARI_CUDA off), there are none, and the
// answers say so; with it, a machine without a driver or a GPU answers the same way.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hikari/core/flat_view.h"

namespace hikari {

/// Where a render's kernels run (`--device`).
enum class ExecutionDevice : uint8_t {
    cpu,   ///< the CPU's threads
    cuda,  ///< an NVIDIA GPU through the CUDA runtime
};

/// One CUDA device, as the runtime describes it.
struct CudaDevice {
    std::string name;
    int compute_major = 0, compute_minor = 0;  ///< compute capability (9.0 for an H100/H200)
    size_t memory_bytes = 0;                   ///< global memory
    int multiprocessors = 0;
};

/// What the CUDA runtime found.
struct CudaDevices {
    bool built = false;   ///< hikari was built with CUDA (HIKARI_CUDA)
    std::string problem;  ///< why no device can be used ("" when some can)
    std::vector<CudaDevice> devices;
};

/// Asks the CUDA runtime (cudaGetDeviceCount, cudaGetDeviceProperties); never throws: a
/// missing driver or device is a `problem`.
CudaDevices find_cuda_devices();

/// InputError, one line naming why, when no CUDA device can run `what` (e.g. "--device cuda").
void require_cuda_device(std::string_view what);

/// InputError naming `what` and the CUDA error when `status` (a cudaError_t) is not success.
void check_cuda(int status, std::string_view what);

/// Memory a render's kernels read and write, freed with the arena: on the CPU, views of the
/// host arrays themselves (nothing copied) and host buffers for the results; on a CUDA device,
/// copies in managed memory, which the host reads back without explicit copies.
class DeviceArena {
  public:
    explicit DeviceArena(ExecutionDevice device) : m_device(device) {}
    DeviceArena(const DeviceArena&) = delete;
    DeviceArena& operator=(const DeviceArena&) = delete;
    ~DeviceArena();

    ExecutionDevice device() const { return m_device; }

    /// `values` where the kernels can read them. The elements are copied bytewise to the device,
    /// so only their plain-data fields may be read there.
    template <class T>
    FlatView<T> hold(std::span<const T> values) {
        if (m_device == ExecutionDevice::cpu || values.empty()) return FlatView<T>(values);
        void* copy = allocate(values.size_bytes());
        std::memcpy(copy, static_cast<const void*>(values.data()), values.size_bytes());
        return FlatView<T>(static_cast<const T*>(copy), values.size());
    }
    /// One value where the kernels can read it.
    template <class T>
    const T* hold_one(const T& value) {
        return hold(std::span<const T>(&value, 1)).data;
    }
    /// `count` zero-filled values the kernels write and the host then reads.
    template <class T>
    T* output(size_t count) {
        void* memory = allocate(count * sizeof(T));
        std::memset(memory, 0, count * sizeof(T));
        return static_cast<T*>(memory);
    }

  private:
    void* allocate(size_t bytes);

    ExecutionDevice m_device;
    std::vector<void*> m_blocks;
};

}  // namespace hikari
