#pragma once
// The registry as data: every method with its summary, options (kind, range or words, help) and
// AOVs, for front ends that build their controls from it (`hikari serve`'s page, hikari.methods()
// in Python), so that a new method appears there without touching them.

#include <nlohmann/json.hpp>

namespace hikari {

/// [{"name", "summary", "options": [{"name", "flag", "help", "kind", "min", "max" | "choices"}],
///   "aovs": [...], "draws_lines", "explain": {"pixel", "row", "whole"}}, ...] in registry order.
/// Option names are the command line's long options without dashes, '-' as '_' (spp,
/// light_samples).
nlohmann::json method_catalog();

}  // namespace hikari
