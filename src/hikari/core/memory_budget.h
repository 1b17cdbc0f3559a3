#pragma once
// The memory limit (`--max-memory`) that every large allocation is checked against before it is
// made, so a hostile or mistaken input is refused with one line instead of exhausting the
// machine.

#include <cstdint>
#include <string>
#include <string_view>

namespace hikari {

/// "1.5 GiB", or "12.0 MiB" below a tenth of a GiB: a size for messages.
std::string memory_size_text(double bytes);

/// The limit in bytes; by default half the machine's physical memory (4 GiB when unknown).
double memory_limit();

/// Sets the limit (bytes > 0; the command line's --max-memory). Process-wide: set it once,
/// before loading and rendering.
void set_memory_limit(double bytes);

/// Throws InputError "WHAT needs about N GiB, more than the limit of M GiB (raise it with
/// --max-memory)" when `bytes` exceed the limit. Call it with the size an allocation is about to
/// take, computed from the counts that decide it (in double, so it cannot overflow).
void check_memory_need(double bytes, std::string_view what);

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
