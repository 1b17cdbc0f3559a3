#pragma once
// What `hikari serve` may read: the scene and model files under its --root folder, and nothing
// outside it (no "..", no absolute paths, no symlink that leads out).

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace hikari::cli {

/// A path a request named that lies outside --root: HTTP 403.
class ForbiddenPath : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// A path a request named that is not there: HTTP 404.
class MissingPath : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// The files under one folder that the server may load.
class ServedFiles {
  public:
    /// `root` must be an existing folder (InputError otherwise).
    explicit ServedFiles(const std::filesystem::path& root);

    const std::filesystem::path& root() const { return m_root; }

    /// The file `relative` names under the root, with every symlink resolved. Throws
    /// ForbiddenPath for an absolute path, a ".." step or a link out of the root, MissingPath
    /// when it is not a regular file there.
    std::filesystem::path resolve(const std::string& relative) const;

    /// The scene (.json) and model (.obj .ply .gltf .glb) files under the root, relative to it,
    /// sorted; at most `limit`, searched at most four folders deep, hidden folders skipped.
    std::vector<std::string> scene_files(size_t limit = 1000) const;

  private:
    std::filesystem::path m_root;  ///< canonical
};

}  // namespace hikari::cli
