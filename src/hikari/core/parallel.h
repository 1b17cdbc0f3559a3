#pragma once
// Parallel loops for every stage: oneTBB's, called through here so that one switch can change
// how they run. Under ThreadSanitizer they run on plain std::threads instead: Debian's libtbb is
// not built with TSan, which then cannot see TBB's synchronization and reports races that cannot
// happen. On std::threads TSan sees every fork and join and still reports any real race between
// two tasks of a loop.

#include <algorithm>
#include <cstddef>
#include <exception>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>
#include <tbb/parallel_sort.h>

#if defined(__SANITIZE_THREAD__)
#define HIKARI_TSAN 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define HIKARI_TSAN 1
#endif
#endif

#ifdef HIKARI_TSAN
#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>
#endif

namespace hikari {

#ifndef HIKARI_TSAN

/// Calls `body(range)` on sub-ranges of `range` on all threads of the current arena.
template <class Range, class Body>
void parallel_for(const Range& range, const Body& body) {
    tbb::parallel_for(range, body);
}

/// Runs `a` and `b`, possibly at the same time.
template <class A, class B>
void parallel_invoke(const A& a, const B& b) {
    tbb::parallel_invoke(a, b);
}

/// tbb::parallel_reduce: `body(range, partial)` returns partial folded with the range, `join(x, y)`
/// combines two partials. For results independent of the thread count, `join` must be associative
/// and exact (min, max, integer sums), since the split points vary from run to run.
template <class Range, class Value, class Body, class Join>
Value parallel_reduce(const Range& range, const Value& identity, const Body& body,
                      const Join& join) {
    return tbb::parallel_reduce(range, identity, body, join);
}

/// Sorts [first, last) by `less` on all threads. Not stable: for a result independent of the
/// thread count, `less` must be a strict total order on the values (break ties by an index).
template <class Iterator, class Less>
void parallel_sort(Iterator first, Iterator last, const Less& less) {
    tbb::parallel_sort(first, last, less);
}

#else

namespace detail {

/// Under TSan: calls `chunk(begin, end)` for consecutive chunks of [first, last) of `grain`
/// indices, pulled from a shared counter by plain std::threads that TSan sees start and join.
template <class Index, class Chunk>
void fork_join(Index first, Index last, Index grain, const Chunk& chunk) {
    if (!(first < last)) return;
    grain = std::max<Index>(grain, 1);
    std::atomic<Index> next{first};
    auto work = [&] {
        for (;;) {
            const Index begin = next.fetch_add(grain);
            if (!(begin < last)) return;
            chunk(begin, static_cast<Index>(std::min<Index>(last - begin, grain) + begin));
        }
    };
    std::vector<std::thread> helpers;
    for (unsigned t = 1; t < std::max(2u, std::thread::hardware_concurrency()); ++t)
        helpers.emplace_back(work);
    work();
    for (std::thread& t : helpers) t.join();
}

}  // namespace detail

template <class Range, class Body>
void parallel_for(const Range& range, const Body& body) {
    using Index = decltype(range.begin());
    const auto grain = static_cast<Index>(range.grainsize());
    detail::fork_join(range.begin(), range.end(), grain,
                      [&](Index b, Index e) { body(Range(b, e, range.grainsize())); });
}

template <class A, class B>
void parallel_invoke(const A& a, const B& b) {
    std::thread helper([&] { a(); });
    b();
    helper.join();
}

template <class Range, class Value, class Body, class Join>
Value parallel_reduce(const Range& range, const Value& identity, const Body& body,
                      const Join& join) {
    using Index = decltype(range.begin());
    const Index grain = std::max<Index>(static_cast<Index>(range.grainsize()), 1);
    const auto count = static_cast<size_t>((range.end() - range.begin() + grain - 1) / grain);
    std::vector<Value> partials(count, identity);
    detail::fork_join(range.begin(), range.end(), grain, [&](Index b, Index e) {
        partials[static_cast<size_t>((b - range.begin()) / grain)] =
            body(Range(b, e, grain), identity);
    });
    Value result = identity;
    for (Value& p : partials) result = join(std::move(result), std::move(p));
    return result;
}

template <class Iterator, class Less>
void parallel_sort(Iterator first, Iterator last, const Less& less) {
    std::sort(first, last, less);
}

#endif

/// Calls `body(i)` for every i in [first, last) on all threads of the current arena.
template <class Index, class Body>
void parallel_for(Index first, Index last, const Body& body) {
    hikari::parallel_for(tbb::blocked_range<Index>(first, last),
                         [&](const tbb::blocked_range<Index>& r) {
                             for (Index i = r.begin(); i != r.end(); ++i) body(i);
                         });
}

/// Calls `body(chunk, begin, end)` for the chunks [begin, end) of [0, count), `chunk_size` items
/// each (the last may be shorter), on all threads. The chunks do not depend on the thread count,
/// so per-chunk results joined in chunk order do not either. An exception thrown by a chunk
/// stops no other; once all have run, the one thrown by the first chunk in order is rethrown
/// (as a loop over the items in order would have thrown it).
template <class Body>
void parallel_chunks(size_t count, size_t chunk_size, const Body& body) {
    chunk_size = std::max<size_t>(chunk_size, 1);
    const size_t chunks = (count + chunk_size - 1) / chunk_size;
    std::vector<std::exception_ptr> failed(chunks);
    hikari::parallel_for(tbb::blocked_range<size_t>(0, chunks, 1),
                         [&](const tbb::blocked_range<size_t>& r) {
                             for (size_t c = r.begin(); c != r.end(); ++c) {
                                 try {
                                     body(c, c * chunk_size, std::min(count, (c + 1) * chunk_size));
                                 } catch (...) {
                                     failed[c] = std::current_exception();
                                 }
                             }
                         });
    for (const std::exception_ptr& e : failed)
        if (e) std::rethrow_exception(e);
}

}  // namespace hikari
