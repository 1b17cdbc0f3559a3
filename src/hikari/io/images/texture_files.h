#pragma once
// Image textures read from files: each file read and its mipmap pyramid built once, however
// many materials refer to it.

#include <filesystem>
#include <map>
#include <memory>

#include "hikari/scene/texture.h"

namespace hikari {

/// The image files of one scene or mesh load, each read once.
class TextureFiles {
  public:
    /// The mipmap pyramid of the image at `path` (any format io/image_read.h reads; 8-bit files
    /// sRGB-decoded to linear), read on first use. Throws InputError naming the file and the
    /// reason when it is missing, unreadable, empty or not an image, or when the pyramids read
    /// so far and this one would need more than --max-memory.
    std::shared_ptr<const MipPyramid> pyramid(const std::filesystem::path& path);

  private:
    std::map<std::filesystem::path, std::shared_ptr<const MipPyramid>> m_read;
    double m_pyramid_bytes = 0;  ///< of every pyramid built so far, for --max-memory
};

}  // namespace hikari
