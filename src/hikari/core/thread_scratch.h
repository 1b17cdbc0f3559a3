#pragma once
// Scratch buffers kept per thread between calls: big temporary arrays (an encoder's per-band
// buffers) allocated once per thread rather than once per call, which on Linux means fresh pages
// from the kernel, each zeroed and faulted in, every time.

#include <cstddef>
#include <memory>

#include "hikari/core/huge_page_allocator.h"

namespace hikari {

/// At least `n` elements of T, uninitialised, owned by the calling thread and reused by its next
/// call with the same T and Tag. Valid until that next call. Tag is a type of the caller's own
/// (an empty struct per buffer), so buffers of different callers never coincide, even when one
/// calls the other while its buffer is in use.
/// A new buffer is mapped at once (populate_pages): cheaper than faulting in, even for pages the
/// caller may not reach (the encoder's worst-case sized outputs; measured on the B3 image).
template <class T, class Tag>
T* thread_scratch(size_t n) {
    thread_local std::unique_ptr<T[]> buffer;
    thread_local size_t capacity = 0;
    if (capacity < n) {
        buffer = std::make_unique_for_overwrite<T[]>(n);
        capacity = n;
        populate_pages(buffer.get(), n * sizeof(T));
    }
    return buffer.get();
}

}  // namespace hikari
