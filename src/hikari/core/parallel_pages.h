#pragma once
// Mapping a large buffer's pages on all threads before it is filled.

#include <algorithm>
#include <cstddef>

#include "hikari/core/huge_page_allocator.h"
#include "hikari/core/parallel.h"

namespace hikari {

/// populate_pages (core/huge_page_allocator.h) over [p, p + bytes), in pieces of a few MiB on
/// all threads: for a large buffer about to be filled, its pages are mapped at once and by every
/// core, not faulted in one by one by the thread that fills it.
inline void populate_pages_in_parallel(void* p, size_t bytes) {
    constexpr size_t k_piece = size_t{4} << 20;
    char* const start = static_cast<char*>(p);
    hikari::parallel_for(size_t{0}, (bytes + k_piece - 1) / k_piece, [&](size_t k) {
        populate_pages(start + k * k_piece, std::min(k_piece, bytes - k * k_piece));
    });
}

}  // namespace hikari
