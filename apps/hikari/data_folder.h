#pragma once
// Where the program finds the files it ships with: the default model and the scenes the gallery
// and the benchmarks start from.

#include <filesystem>

namespace hikari::cli {

/// The folder that holds hikari's `scenes/` (scenes/models/teapot.json, scenes/whitted.json ...):
/// `$HIKARI_DATA_DIR` when set; else `<prefix>/share/hikari` beside an installed program
/// (`<prefix>/bin/hikari`, as `cmake --install` lays them out); else the source tree the program
/// was built from. Throws InputError naming the places looked in when none holds `scenes/`.
std::filesystem::path data_folder();

}  // namespace hikari::cli
