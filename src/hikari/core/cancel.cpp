#include "hikari/core/cancel.h"

#include <atomic>

#include "hikari/core/error.h"

namespace hikari {

namespace {

// Lock-free, so that a signal handler may store to it (POSIX.1-2017, 2.4.3).
std::atomic<bool> g_cancel_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free);

}  // namespace

void request_cancel() noexcept { g_cancel_requested.store(true, std::memory_order_relaxed); }

void clear_cancel_request() noexcept { g_cancel_requested.store(false, std::memory_order_relaxed); }

bool cancel_requested() noexcept { return g_cancel_requested.load(std::memory_order_relaxed); }

void throw_if_cancelled() {
    if (cancel_requested()) throw Interrupted();
}

}  // namespace hikari
