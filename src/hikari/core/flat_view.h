#pragma once
// A read-only view of a flat array that host and device code index alike (std::span is not
// callable from CUDA device code): what the GPU kernels read instead of std::vector.

#include <cstddef>
#include <span>

#include "hikari/core/host_device.h"

namespace hikari {

/// `count` elements at `data`, in host memory or in memory the GPU reads (core/cuda_devices.h,
/// DeviceArena); the view owns nothing.
template <class T>
struct FlatView {
    const T* data = nullptr;
    size_t count = 0;

    FlatView() = default;
    /// A view of the elements of a host array (a std::vector, a std::span).
    FlatView(std::span<const T> s) : data(s.data()), count(s.size()) {}  // NOLINT: a view
    HIKARI_HD FlatView(const T* d, size_t n) : data(d), count(n) {}

    HIKARI_HD const T& operator[](size_t i) const { return data[i]; }
    HIKARI_HD size_t size() const { return count; }
    HIKARI_HD bool empty() const { return count == 0; }
};

}  // namespace hikari
