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

}  // namespace

double memory_limit() { return limit().load(); }

void set_memory_limit(double bytes) {
    if (bytes > 0.0) limit().store(bytes);
}

void check_memory_need(double bytes, std::string_view what) {
    const double cap = memory_limit();
    if (!(bytes > cap)) return;
    constexpr double gib = 1 << 30;
    throw InputError(fmt::format(
        "{} needs about {:.1f} GiB, more than the limit of {:.1f} GiB (raise it with --max-memory)",
        what, bytes / gib, cap / gib));
}

}  // namespace hikari
