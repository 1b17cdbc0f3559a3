#include "hikari/shading/textures/image_texture.h"

#include <algorithm>
#include <cmath>

namespace hikari {

namespace {

/// A coordinate brought near [0, 1] before it is scaled to texels, so that far repeats keep
/// their fraction and nothing overflows an int: repeat keeps u − floor(u); clamp needs nothing
/// beyond one texel outside. NaN becomes 0.
float reduce_coordinate(float u, TextureWrap wrap) {
    if (!std::isfinite(u)) return std::isnan(u) ? 0.0f : (u > 0 ? 1.0f : 0.0f);
    if (wrap == TextureWrap::repeat) return u - std::floor(u);
    return std::clamp(u, -1.0f, 2.0f);
}

/// Texel (x, y) counted from the lower-left corner, wrapped.
const Vec3& texel_from_bottom(const Image& level, int x, int y, TextureWrap wrap) {
    const int column = wrap_texel(x, level.width, wrap);
    const int row_from_bottom = wrap_texel(y, level.height, wrap);
    return level.at(column, level.height - 1 - row_from_bottom);
}

}  // namespace

int wrap_texel(int i, int size, TextureWrap wrap) {
    if (wrap == TextureWrap::clamp) return std::clamp(i, 0, size - 1);
    const int r = i % size;
    return r < 0 ? r + size : r;
}

Vec3 sample_nearest(const Image& level, float u, float v, TextureWrap wrap) {
    const float s = reduce_coordinate(u, wrap) * static_cast<float>(level.width);
    const float t = reduce_coordinate(v, wrap) * static_cast<float>(level.height);
    return texel_from_bottom(level, static_cast<int>(std::floor(s)),
                             static_cast<int>(std::floor(t)), wrap);
}

Vec3 sample_bilinear(const Image& level, float u, float v, TextureWrap wrap) {
    // Texel centres sit at half-integer texel coordinates: shift by half a texel, then blend
    // the four centres around the point.
    const float s = reduce_coordinate(u, wrap) * static_cast<float>(level.width) - 0.5f;
    const float t = reduce_coordinate(v, wrap) * static_cast<float>(level.height) - 0.5f;
    const float x0f = std::floor(s), y0f = std::floor(t);
    const float fx = s - x0f, fy = t - y0f;
    const int x0 = static_cast<int>(x0f), y0 = static_cast<int>(y0f);
    const Vec3 bottom = texel_from_bottom(level, x0, y0, wrap) * (1.0f - fx) +
                        texel_from_bottom(level, x0 + 1, y0, wrap) * fx;
    const Vec3 top = texel_from_bottom(level, x0, y0 + 1, wrap) * (1.0f - fx) +
                     texel_from_bottom(level, x0 + 1, y0 + 1, wrap) * fx;
    return bottom * (1.0f - fy) + top * fy;
}

float mip_level_of_detail(const MipPyramid& pyramid, float du_dx, float dv_dx, float du_dy,
                          float dv_dy) {
    const Image& base = pyramid.levels.front();
    const auto w = static_cast<float>(base.width), h = static_cast<float>(base.height);
    const float along_x = std::hypot(du_dx * w, dv_dx * h);
    const float along_y = std::hypot(du_dy * w, dv_dy * h);
    const float texels = std::max(along_x, along_y);
    if (!(texels > 1.0f)) return 0.0f;  // magnified, zero or NaN: the finest level
    const auto coarsest = static_cast<float>(pyramid.levels.size() - 1);
    return std::min(std::log2(texels), coarsest);
}

Vec3 sample_image_texture(const ImageTexture& texture, float u, float v, float du_dx, float dv_dx,
                          float du_dy, float dv_dy) {
    const MipPyramid& pyramid = *texture.pyramid;
    switch (texture.filter) {
        case TextureFilter::nearest:
            return sample_nearest(pyramid.levels.front(), u, v, texture.wrap);
        case TextureFilter::bilinear:
            return sample_bilinear(pyramid.levels.front(), u, v, texture.wrap);
        case TextureFilter::trilinear:
            break;
    }
    const float lod = mip_level_of_detail(pyramid, du_dx, dv_dx, du_dy, dv_dy);
    const auto fine = static_cast<size_t>(lod);
    const float blend = lod - static_cast<float>(fine);
    const Vec3 a = sample_bilinear(pyramid.levels[fine], u, v, texture.wrap);
    if (blend == 0.0f || fine + 1 >= pyramid.levels.size()) return a;
    const Vec3 b = sample_bilinear(pyramid.levels[fine + 1], u, v, texture.wrap);
    return a * (1.0f - blend) + b * blend;
}

}  // namespace hikari
