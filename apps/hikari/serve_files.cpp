#include "serve_files.h"

#include <algorithm>
#include <system_error>

#include <fmt/format.h>

#include "hikari/core/error.h"
#include "hikari/io/files/printable_text.h"
#include "hikari/io/models/model_file.h"

namespace hikari::cli {

namespace fs = std::filesystem;

namespace {

/// Whether `path` (canonical) is `root` or lies under it.
bool is_under(const fs::path& path, const fs::path& root) {
    auto p = path.begin();
    for (auto r = root.begin(); r != root.end(); ++r, ++p)
        if (p == path.end() || *p != *r) return false;
    return true;
}

bool is_scene_file(const fs::path& path) {
    return path.extension() == ".json" || is_model_file(path);
}

}  // namespace

ServedFiles::ServedFiles(const fs::path& root) {
    std::error_code ec;
    m_root = fs::canonical(root, ec);
    if (ec || !fs::is_directory(m_root))
        throw InputError(fmt::format("--root {}: not a folder", printable_text(root.string())));
}

fs::path ServedFiles::resolve(const std::string& relative) const {
    const fs::path asked(relative);
    if (relative.empty() || asked.is_absolute())
        throw ForbiddenPath(fmt::format("'{}': give a path relative to the served folder",
                                        printable_text(relative)));
    for (const fs::path& step : asked)
        if (step == "..")
            throw ForbiddenPath(
                fmt::format("'{}': \"..\" leaves the served folder", printable_text(relative)));
    std::error_code ec;
    const fs::path path = fs::canonical(m_root / asked, ec);
    if (ec || !fs::is_regular_file(path))
        throw MissingPath(
            fmt::format("'{}': no such file under the served folder", printable_text(relative)));
    if (!is_under(path, m_root))
        throw ForbiddenPath(fmt::format("'{}': a link that leads out of the served folder",
                                        printable_text(relative)));
    return path;
}

std::vector<std::string> ServedFiles::scene_files(size_t limit) const {
    std::vector<std::string> files;
    std::error_code ec;
    fs::recursive_directory_iterator it(m_root, fs::directory_options::skip_permission_denied, ec);
    for (; !ec && it != fs::recursive_directory_iterator() && files.size() < limit;
         it.increment(ec)) {
        const fs::path& path = it->path();
        const bool hidden = path.filename().string().starts_with(".");
        if (it->is_directory(ec)) {
            if (hidden || it.depth() >= 3) it.disable_recursion_pending();
            continue;
        }
        // Only what resolve() would serve: no link that leads out.
        if (!hidden && is_scene_file(path) && it->is_regular_file(ec) &&
            is_under(fs::canonical(path, ec), m_root) && !ec)
            files.push_back(path.lexically_relative(m_root).generic_string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace hikari::cli
