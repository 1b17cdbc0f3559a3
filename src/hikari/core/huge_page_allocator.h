#pragma once
// An allocator for the big per-image buffers (framebuffers, encoded images). Touching fresh
// memory costs one page fault per 4 KiB page, and on a virtual machine a fault costs microseconds:
// a 1920×1080 float image alone is some 6000 faults. Buffers of 2 MiB or more are mapped on
// their own and marked MADV_HUGEPAGE, so that with transparent huge pages in `madvise` mode
// (the common default) they fault in 2 MiB at a time. Smaller buffers use the ordinary heap.

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <new>
#include <vector>

namespace hikari {

/// A std::allocator that backs allocations of k_huge_page_bytes or more with huge pages when the
/// system grants them (it may not: the memory then behaves like any other).
template <class T>
struct HugePageAllocator {
    using value_type = T;
    static constexpr size_t k_huge_page_bytes = size_t{2} << 20;

    HugePageAllocator() = default;
    template <class U>
    HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

    T* allocate(size_t n) {
        if (n > SIZE_MAX / sizeof(T)) throw std::bad_array_new_length();
        const size_t bytes = n * sizeof(T);
        if (bytes < k_huge_page_bytes) return std::allocator<T>().allocate(n);
        void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (p == MAP_FAILED) throw std::bad_alloc();
        // Advice only: failure leaves ordinary pages, which work the same.
        madvise(p, bytes, MADV_HUGEPAGE);
        return static_cast<T*>(p);
    }

    void deallocate(T* p, size_t n) noexcept {
        const size_t bytes = n * sizeof(T);
        if (bytes < k_huge_page_bytes)
            std::allocator<T>().deallocate(p, n);
        else
            munmap(p, bytes);
    }

    template <class U>
    bool operator==(const HugePageAllocator<U>&) const noexcept {
        return true;
    }
};

/// A vector whose large buffers use huge pages.
template <class T>
using HugePageVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace hikari
