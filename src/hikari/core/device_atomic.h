#pragma once
// The one atomic operation the wavefront kernels need (issue 46): appending to a queue, a flat
// array with a counter. atomicAdd on the GPU, std::atomic_ref on the CPU; written once, HIKARI_HD.
// Only the slot an entry lands in depends on the threads' timing; each entry carries what it
// belongs to (its path), so nothing computed depends on the order.

#include <atomic>
#include <cstdint>

#include "hikari/core/host_device.h"

namespace hikari {

/// Adds 1 to `*counter` atomically and returns the value it had: the slot of a queue's new entry.
HIKARI_HD inline uint32_t atomic_increment(uint32_t* counter) {
#if HIKARI_DEVICE_PASS
    return atomicAdd(counter, 1u);
#else
    return std::atomic_ref<uint32_t>(*counter).fetch_add(1u, std::memory_order_relaxed);
#endif
}

}  // namespace hikari
