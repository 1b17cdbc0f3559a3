#include "hikari/io/files/input_limits.h"

#include <atomic>

namespace hikari {
namespace {

/// 0 = no override: each kind keeps its default.
std::atomic<std::uintmax_t>& override_bytes() {
    static std::atomic<std::uintmax_t> bytes{0};
    return bytes;
}

}  // namespace

std::uintmax_t input_limit(InputKind kind) {
    if (const std::uintmax_t bytes = override_bytes().load(); bytes > 0) return bytes;
    constexpr std::uintmax_t mib = std::uintmax_t{1} << 20;
    switch (kind) {
        case InputKind::scene:
            return 256 * mib;
        case InputKind::mesh:
            return 4096 * mib;
        case InputKind::image:
            return 1024 * mib;
    }
    return 4096 * mib;
}

std::string_view input_kind_name(InputKind kind) {
    switch (kind) {
        case InputKind::scene:
            return "scene";
        case InputKind::mesh:
            return "mesh";
        case InputKind::image:
            return "image";
    }
    return "input";
}

void set_max_input_size(std::uintmax_t bytes) { override_bytes().store(bytes); }

}  // namespace hikari
