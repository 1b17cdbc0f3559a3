#include "hikari/core/memory_budget.h"

#include <fmt/format.h>
#include <unistd.h>

#include <atomic>

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

}  // namespace

std::string memory_size_text(double bytes) {
    constexpr double mib = 1 << 20, gib = 1 << 30;
    if (bytes >= 0.1 * gib) return fmt::format("{:.1f} GiB", bytes / gib);
    return fmt::format("{:.1f} MiB", bytes / mib);
}

double memory_limit() { return limit().load(); }

void set_memory_limit(double bytes) {
    if (bytes > 0.0) limit().store(bytes);
}

void check_memory_need(double bytes, std::string_view what) {
    const double cap = memory_limit();
    const double kept = held().load();
    if (!(bytes + kept > cap)) return;
    const std::string besides =
        kept > 0 ? fmt::format(" besides the {} already held", memory_size_text(kept)) : "";
    throw InputError(
        fmt::format("{} needs about {}{}, more than the limit of {} (raise it with "
                    "--max-memory)",
                    what, memory_size_text(bytes), besides, memory_size_text(cap)));
}

MemoryHeld::MemoryHeld(double bytes) : m_bytes(bytes) { held().fetch_add(bytes); }

MemoryHeld::~MemoryHeld() { held().fetch_sub(m_bytes); }

}  // namespace hikari
