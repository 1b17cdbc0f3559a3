#include "hikari/io/images/texture_files.h"

#include <fmt/format.h>

#include "hikari/core/memory_budget.h"
#include "hikari/io/images/image_read.h"
#include "hikari/shading/textures/mip_pyramid.h"

namespace hikari {

std::shared_ptr<const MipPyramid> TextureFiles::pyramid(const std::filesystem::path& path) {
    const std::filesystem::path key = path.lexically_normal();
    auto found = m_read.find(key);
    if (found != m_read.end()) return found->second;
    Image base = read_image(path);
    // A pyramid holds its base level's RGB floats and a third more for the smaller levels.
    const double bytes = 12.0 * base.width * base.height * 4.0 / 3.0;
    check_memory_need(m_pyramid_bytes + bytes,
                      fmt::format("{}: the mipmap pyramid of a {}x{} texture", path.string(),
                                  base.width, base.height));
    m_pyramid_bytes += bytes;
    auto built = std::make_shared<const MipPyramid>(build_mip_pyramid(std::move(base)));
    m_read.emplace(key, built);
    return built;
}

}  // namespace hikari
