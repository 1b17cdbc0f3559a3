#include "hikari/core/memory_budget.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <mutex>

#if defined(__SANITIZE_ADDRESS__)
#define HIKARI_MEMORY_FROM_ALLOCATOR 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define HIKARI_MEMORY_FROM_ALLOCATOR 1
#endif
#endif
#ifdef HIKARI_MEMORY_FROM_ALLOCATOR
#include <sanitizer/allocator_interface.h>
#endif

#include "hikari/core/error.h"

namespace hikari {
namespace {

double physical_memory_half() {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? 0.5 * static_cast<double>(pages) * static_cast<double>(page)
                                 : 4.0 * (1 << 30);
}

std::atomic<double>& limit() {
    static std::atomic<double> bytes{physical_memory_half()};
    return bytes;
}

std::atomic<double>& held() {
    static std::atomic<double> bytes{0.0};
    return bytes;
}

/// Needs below this are checked against the explicit holds alone: reading the process's memory
/// costs a system call, and a need this small never decides a refusal.
constexpr double k_least_need_to_measure = double(1 << 20);

struct ScopeState {
    std::mutex mutex;
    int depth = 0;
    double start = 0;
};

ScopeState& scope() {
    static ScopeState state;
    return state;
}

std::atomic<double> g_scope_start{-1.0};  ///< the outermost scope's start; < 0: none open

std::string& limit_hint() {
    static std::string hint = "--max-memory GIB";
    return hint;
}

/// `value` rounded up to `digits` significant digits (value > 0), so that a need or a limit
/// to ask for never reads smaller than it is.
double round_up(double value, int digits) {
    if (!(value > 0) || !std::isfinite(value)) return value;
    const double scale = std::pow(10.0, digits - 1 - std::floor(std::log10(value)));
    const double rounded = std::ceil(value * scale * (1 - 1e-12)) / scale;
    return std::max(rounded, value);
}

/// How to raise the limit to `bytes`: the hint with GIB replaced by that many GiB, rounded up
/// to two significant digits (the value to pass, not the limit's own rounding).
std::string raise_hint(double bytes) {
    const std::string gib = fmt::format("{:g}", round_up(bytes / double(1 << 30), 2));
    std::string hint = limit_hint();
    if (const size_t at = hint.find("GIB"); at != std::string::npos)
        return hint.replace(at, 3, gib) + " or more";
    return fmt::format("{}, to {} GiB or more", hint, gib);
}

}  // namespace

double process_memory_bytes() {
#ifdef HIKARI_MEMORY_FROM_ALLOCATOR
    return static_cast<double>(__sanitizer_get_current_allocated_bytes());
#else
    // One descriptor, read with pread: a few microseconds, safe from any thread.
    static const int fd = ::open("/proc/self/statm", O_RDONLY | O_CLOEXEC);
    char text[128];
    const ssize_t n = fd >= 0 ? ::pread(fd, text, sizeof text - 1, 0) : -1;
    if (n <= 0) return 0;
    text[n] = 0;
    long pages_total = 0, pages_resident = 0;
    if (std::sscanf(text, "%ld %ld", &pages_total, &pages_resident) != 2) return 0;
    return static_cast<double>(pages_resident) * static_cast<double>(::sysconf(_SC_PAGESIZE));
#endif
}

MemoryScope::MemoryScope() {
    ScopeState& s = scope();
    std::lock_guard lock(s.mutex);
    if (s.depth++ == 0) g_scope_start.store(process_memory_bytes());
}

MemoryScope::~MemoryScope() {
    ScopeState& s = scope();
    std::lock_guard lock(s.mutex);
    if (--s.depth == 0) g_scope_start.store(-1.0);
}

double MemoryScope::grown_bytes() {
    const double start = g_scope_start.load();
    if (start < 0) return 0;
    return std::max(0.0, process_memory_bytes() - start);
}

void set_memory_limit_hint(std::string hint) { limit_hint() = std::move(hint); }

std::string memory_size_text(double bytes) {
    constexpr double mib = 1 << 20, gib = 1 << 30;
    const bool in_gib = bytes >= 0.1 * gib;
    return fmt::format("{:g} {}", round_up(bytes / (in_gib ? gib : mib), 3),
                       in_gib ? "GiB" : "MiB");
}

std::string memory_limit_text(double bytes) {
    constexpr double mib = 1 << 20, gib = 1 << 30;
    if (bytes >= 0.1 * gib) return fmt::format("{:.6g} GiB", bytes / gib);
    return fmt::format("{:.6g} MiB", bytes / mib);
}

double memory_limit() { return limit().load(); }

void set_memory_limit(double bytes) {
    if (bytes > 0.0) limit().store(bytes);
}

void check_memory_need(double bytes, std::string_view what) {
    const double cap = memory_limit();
    double kept = held().load();
    if (bytes >= k_least_need_to_measure) kept += MemoryScope::grown_bytes();
    if (!(bytes + kept > cap)) return;
    const std::string besides =
        kept > 0 ? fmt::format(" besides the {} already held", memory_size_text(kept)) : "";
    throw InputError(fmt::format(
        "{} needs about {}{}, more than the limit of {} (raise it with {})", what,
        memory_size_text(bytes), besides, memory_limit_text(cap), raise_hint(bytes + kept)));
}

MemoryHeld::MemoryHeld(double bytes) : m_bytes(bytes) { held().fetch_add(bytes); }

MemoryHeld::~MemoryHeld() { held().fetch_sub(m_bytes); }

}  // namespace hikari
