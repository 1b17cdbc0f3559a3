#pragma once
// The words Python callers use for AOVs: the command line's --aov words (methods/
// method_options.h), with "paint_order" taken for "paint-order" as a keyword would spell it.

#include <optional>
#include <string_view>

#include "hikari/methods/method_options.h"

namespace hikari::python {

/// The AOV `word` names, or nullopt.
inline std::optional<Aov> aov_named(std::string_view word) {
    if (word == "paint_order") return Aov::paint_order;
    return choice_value<Aov>(k_aov_choices, word);
}

}  // namespace hikari::python
