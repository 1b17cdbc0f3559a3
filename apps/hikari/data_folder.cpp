#include "data_folder.h"

#include <cstdlib>
#include <string>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "hikari/core/error.h"

namespace hikari::cli {

namespace fs = std::filesystem;

namespace {

/// `<prefix>/share/hikari` for the running program `<prefix>/bin/hikari` (Linux's
/// /proc/self/exe; empty where it cannot be read).
fs::path installed_data_folder() {
    std::error_code ec;
    const fs::path program = fs::read_symlink("/proc/self/exe", ec);
    if (ec || program.empty()) return {};
    return program.parent_path().parent_path() / "share" / "hikari";
}

}  // namespace

fs::path data_folder() {
    std::vector<fs::path> candidates;
    if (const char* env = std::getenv("HIKARI_DATA_DIR"); env && *env) candidates.emplace_back(env);
    if (fs::path installed = installed_data_folder(); !installed.empty())
        candidates.push_back(std::move(installed));
    candidates.emplace_back(HIKARI_SOURCE_DIR);
    std::string looked;
    for (const fs::path& folder : candidates) {
        std::error_code ec;
        if (fs::is_directory(folder / "scenes" / "models", ec)) return folder;
        looked += (looked.empty() ? "" : ", ") + (folder / "scenes").string();
    }
    throw InputError(fmt::format(
        "cannot find hikari's scenes (looked in {}); install hikari with `cmake --install`, or "
        "set HIKARI_DATA_DIR to a folder that holds scenes/",
        looked));
}

}  // namespace hikari::cli
