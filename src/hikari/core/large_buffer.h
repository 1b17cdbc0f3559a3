#pragma once
// Big arrays (BVH nodes and triangles, framebuffers) on 2 MiB pages where the kernel offers
// them (Linux transparent huge pages in "madvise" mode). Incoherent rays touch the whole tree in
// random order: with 4 KiB pages nearly every node visit of a large mesh also misses the TLB,
// and first touches of fresh memory cost one page fault per 4 KiB, which is slow in VMs.

#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace hikari {

/// Buffers of at least this many bytes are aligned to and advised as huge pages.
inline constexpr size_t k_huge_page_bytes = size_t(2) << 20;

/// Alignment of every buffer: a cache line.
inline constexpr size_t k_cache_line = 64;

/// Allocates `bytes` (huge-page backed when large), never null; throws std::bad_alloc.
inline void* allocate_large(size_t bytes) {
    if (bytes < k_huge_page_bytes) {
        // Cache-line aligned, which covers every over-aligned element type (SIMD nodes).
        const size_t rounded = (bytes + k_cache_line - 1) / k_cache_line * k_cache_line;
        if (void* p = std::aligned_alloc(k_cache_line, rounded == 0 ? k_cache_line : rounded))
            return p;
        throw std::bad_alloc();
    }
    const size_t rounded = (bytes + k_huge_page_bytes - 1) / k_huge_page_bytes * k_huge_page_bytes;
    void* p = std::aligned_alloc(k_huge_page_bytes, rounded);
    if (p == nullptr) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    madvise(p, rounded, MADV_HUGEPAGE);  // advice only: without THP it is plain memory
#endif
    return p;
}

/// A std::allocator replacement for large arrays: huge pages for big buffers.
template <typename T>
struct LargeBufferAllocator {
    using value_type = T;
    LargeBufferAllocator() = default;
    template <typename U>
    constexpr LargeBufferAllocator(const LargeBufferAllocator<U>&) noexcept {}
    static_assert(alignof(T) <= k_cache_line);
    T* allocate(size_t n) {
        if (n > size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
        return static_cast<T*>(allocate_large(n * sizeof(T)));
    }
    void deallocate(T* p, size_t) noexcept { std::free(p); }
    template <typename U>
    bool operator==(const LargeBufferAllocator<U>&) const noexcept {
        return true;
    }
};

/// A vector whose storage may live on huge pages.
template <typename T>
using LargeVector = std::vector<T, LargeBufferAllocator<T>>;

}  // namespace hikari
