#pragma once
// The process-wide request to stop (SIGINT / SIGTERM), which long library stages poll.

namespace hikari {

/// Asks every long stage (loading, BVH build, encoding) to stop at its next poll. Async-signal-
/// safe (one lock-free atomic store): the program's SIGINT / SIGTERM handler calls it.
void request_cancel() noexcept;

/// Withdraws request_cancel(), for a front end that goes on after an interruption (the Python
/// module, once the stage that Ctrl-C stopped has ended): later stages run again.
void clear_cancel_request() noexcept;

/// Whether request_cancel() has been called. Cheap (a relaxed atomic load): loops call it every
/// few thousand items.
bool cancel_requested() noexcept;

/// Throws hikari::Interrupted (core/error.h) when request_cancel() has been called: the one-line
/// poll of a long loop. The caller writes nothing partial; the program exits 130 or 143.
void throw_if_cancelled();

}  // namespace hikari
