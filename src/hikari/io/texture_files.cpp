#include "hikari/io/texture_files.h"

#include "hikari/io/image_read.h"
#include "hikari/shading/textures/mip_pyramid.h"

namespace hikari {

std::shared_ptr<const MipPyramid> TextureFiles::pyramid(const std::filesystem::path& path) {
    const std::filesystem::path key = path.lexically_normal();
    auto found = m_read.find(key);
    if (found != m_read.end()) return found->second;
    auto built = std::make_shared<const MipPyramid>(build_mip_pyramid(read_image(path)));
    m_read.emplace(key, built);
    return built;
}

}  // namespace hikari
