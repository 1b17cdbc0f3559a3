#pragma once
// An allocator for big arrays: framebuffers, encoded images, BVH nodes and triangles. Touching
// fresh memory costs one page fault per 4 KiB page, and on a virtual machine a fault costs
// microseconds: a 1920×1080 float image alone is some 6000 faults. Incoherent rays also visit a
// large tree in random order, and with 4 KiB pages nearly every node visit of a big mesh misses
// the TLB too. Buffers of 2 MiB or more are therefore aligned to 2 MiB and marked
// MADV_HUGEPAGE, so that with transparent huge pages in `madvise` mode (the common default)
// they fault in, and map, 2 MiB at a time. Smaller buffers use the ordinary heap.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace hikari {

#if defined(__linux__)
/// madvise over every page that [p, p + bytes) touches: its start rounded down to a page (the
/// kernel rounds the length up). Advice only: a refusal leaves the memory as it was.
inline void advise_pages(void* p, size_t bytes, int advice) {
    constexpr uintptr_t k_page = 4096;
    if (bytes == 0) return;
    char* const start = static_cast<char*>(p) - reinterpret_cast<uintptr_t>(p) % k_page;
    madvise(start, static_cast<size_t>(static_cast<char*>(p) - start) + bytes, advice);
}
#endif

/// Maps the pages of [p, p + bytes) now, in one call, instead of faulting them in one by one as
/// they are first written. For memory about to be filled: on the SPEC's virtual machine a fault
/// costs some 13 us and population about 2 us a page (docs/performance.md). Population writes
/// nothing, so a page shared with another allocation is only mapped early. Where it is refused
/// (Linux before 5.14, other systems) the memory faults in as usual.
inline void populate_pages([[maybe_unused]] void* p, [[maybe_unused]] size_t bytes) {
#if defined(__linux__)
    constexpr int k_populate_write = 23;  // MADV_POPULATE_WRITE, Linux 5.14
    advise_pages(p, bytes, k_populate_write);
#endif
}

/// Asks the kernel to back the pages of [p, p + bytes) with 2 MiB pages where it can, and
/// (populate) to map them all now rather than fault them in one by one. Advice only: where it
/// is refused the memory works the same.
inline void prepare_huge_pages([[maybe_unused]] void* p, [[maybe_unused]] size_t bytes,
                               [[maybe_unused]] bool populate) {
#if defined(__linux__)
    constexpr size_t k_huge_page = size_t{2} << 20;
    if (bytes < k_huge_page) return;
    advise_pages(p, bytes, MADV_HUGEPAGE);
    if (populate) populate_pages(p, bytes);
#endif
}

/// Maps about `bytes` more of the heap now, for many small allocations to come (a parser's
/// per-line arrays): blocks are taken from malloc, their pages mapped in one call each
/// (populate_pages: some 2 us a page on the SPEC's virtual machine, against 14 us for a fault),
/// and given back, so that malloc hands out mapped pages next. That needs malloc to keep freed
/// memory and to take such blocks from the heap, as main's keep_freed_memory has it; where a
/// block is mapped on its own instead (glibc's default thresholds, other systems), it is given
/// back at once and nothing changes.
inline void reserve_heap(size_t bytes) {
#if defined(__linux__) && defined(__GLIBC__)
    constexpr size_t k_block = size_t{16} << 20;  // under keep_freed_memory's mmap threshold
    std::vector<void*> blocks;
    for (size_t reserved = 0; reserved < bytes; reserved += k_block) {
        const size_t size = std::min(k_block, bytes - reserved);
        void* p = std::malloc(size);
        if (p == nullptr) break;
        blocks.push_back(p);
        // Below the program break: the block is heap memory, which malloc keeps when freed.
        if (static_cast<char*>(p) + size > static_cast<char*>(sbrk(0))) break;
        populate_pages(p, size);
    }
    for (void* block : blocks) std::free(block);
#else
    (void)bytes;
#endif
}

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
        // Whole, aligned huge pages: the kernel only maps 2 MiB pages at 2 MiB boundaries.
        const size_t rounded =
            (bytes + k_huge_page_bytes - 1) / k_huge_page_bytes * k_huge_page_bytes;
        void* p = std::aligned_alloc(k_huge_page_bytes, rounded);
        if (p == nullptr) throw std::bad_alloc();
        prepare_huge_pages(p, rounded, false);
        return static_cast<T*>(p);
    }

    void deallocate(T* p, size_t n) noexcept {
        if (n * sizeof(T) < k_huge_page_bytes)
            std::allocator<T>().deallocate(p, n);
        else
            std::free(p);
    }

    template <class U>
    bool operator==(const HugePageAllocator<U>&) const noexcept {
        return true;
    }
};

/// A vector whose large buffers use huge pages.
template <class T>
using HugePageVector = std::vector<T, HugePageAllocator<T>>;

/// HugePageAllocator whose vectors leave new elements default-initialised (for a byte or a float:
/// not written at all), for buffers whose every element is written before it is read: a pass of
/// zeros first would only cost time.
template <class T>
struct UninitializedHugePageAllocator : HugePageAllocator<T> {
    using value_type = T;
    template <class U>
    struct rebind {
        using other = UninitializedHugePageAllocator<U>;
    };

    UninitializedHugePageAllocator() = default;
    template <class U>
    UninitializedHugePageAllocator(const UninitializedHugePageAllocator<U>&) noexcept {}

    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

}  // namespace hikari
