#pragma once
// The words Python callers use for AOVs, as the command line's --aov takes them.

#include <optional>
#include <string_view>

#include "hikari/frame/framebuffer.h"

namespace hikari::python {

/// An AOV and its word.
struct AovWord {
    std::string_view word;
    Aov aov;
};

inline constexpr AovWord k_aov_words[] = {
    {"color", Aov::color},       {"depth", Aov::depth},       {"id", Aov::id},
    {"normal", Aov::normal},     {"ambient", Aov::ambient},   {"diffuse", Aov::diffuse},
    {"specular", Aov::specular}, {"overdraw", Aov::overdraw}, {"paint-order", Aov::paint_order},
    {"spans", Aov::spans},       {"culled", Aov::culled}};

/// The AOV `word` names ("paint_order" as well as "paint-order"), or nullopt.
inline std::optional<Aov> aov_named(std::string_view word) {
    for (const AovWord& a : k_aov_words) {
        if (a.word == word) return a.aov;
        if (a.word == "paint-order" && word == "paint_order") return a.aov;
    }
    return std::nullopt;
}

}  // namespace hikari::python
