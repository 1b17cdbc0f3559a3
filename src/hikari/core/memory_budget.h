#pragma once
// The memory limit (`--max-memory`) that every large allocation is checked against before it is
// made, so a hostile or mistaken input is refused with one line instead of exhausting the
// machine.

#include <cstdint>
#include <string>
#include <string_view>

namespace hikari {

/// "1.51 GiB", or "12.1 MiB" below a tenth of a GiB: a size for messages, rounded up to three
/// significant digits (a need never reads smaller than it is).
std::string memory_size_text(double bytes);

/// "0.25 GiB" (or "16 MiB" below a tenth of a GiB): a limit to six significant digits, so that
/// it reads as it was given and a need just above it never reads equal to it.
std::string memory_limit_text(double bytes);

/// The limit in bytes; by default half the machine's physical memory (4 GiB when unknown).
double memory_limit();

/// Sets the limit (bytes > 0; the command line's --max-memory). Process-wide: set it once,
/// before loading and rendering.
void set_memory_limit(double bytes);

/// Throws InputError "WHAT needs about N GiB, more than the limit of M GiB (raise it with
/// --max-memory K or more)" when `bytes` exceed the limit, K being what it needs with what is
/// held, in GiB rounded up to two significant digits. Call it with the size an allocation is about
/// to take, computed from the counts that decide it (in double, so it cannot overflow). What is
/// already held counts with it: every MemoryHeld, and inside a MemoryScope what the process's
/// memory has grown since the scope began, so the buffers of one render are checked together
/// (its image, BVH, shadow maps, tessellation, ray tree), not each alone.
void check_memory_need(double bytes, std::string_view what);

/// How the refusal says to raise the limit: "--max-memory GIB" (the command line) by default,
/// GIB standing for the number of GiB needed; the Python module says its own keyword.
void set_memory_limit_hint(std::string hint);

/// The memory the process holds now: its resident set (Linux /proc/self/statm); under
/// AddressSanitizer, the bytes its allocator has handed out (the resident set there carries
/// shadow memory and the quarantine of freed blocks).
double process_memory_bytes();

/// While alive, what the process's memory grows beyond its size when the outermost scope began
/// counts as held (check_memory_need): a load or a render opens one, so every buffer it has made
/// counts against the limit together with the next. Scopes nest: the outermost sets the start.
class MemoryScope {
  public:
    MemoryScope();
    ~MemoryScope();
    MemoryScope(const MemoryScope&) = delete;
    MemoryScope& operator=(const MemoryScope&) = delete;
    /// The growth since the outermost scope began (0 when it shrank).
    static double grown_bytes();
};

/// While alive, `bytes` count as held: check_memory_need() adds them to every need it checks,
/// so a step that keeps one large result while it makes the next (`compare` decoding its second
/// image) stays under the limit in all.
class MemoryHeld {
  public:
    explicit MemoryHeld(double bytes);
    ~MemoryHeld();
    MemoryHeld(const MemoryHeld&) = delete;
    MemoryHeld& operator=(const MemoryHeld&) = delete;

  private:
    double m_bytes;
};

}  // namespace hikari
