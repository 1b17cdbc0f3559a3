#pragma once
// Textures as plain data: the closed set of kinds a material can carry. How each is evaluated
// at a surface point is in shading/textures/ (one file per kind).

#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "hikari/core/image.h"
#include "hikari/core/vec.h"

namespace hikari {

/// A solid checker (POV-Ray's `checker` pattern): colour_a where
/// floor((x + offset.x) / size) + floor((y + offset.y) / size) + floor((z + offset.z) / size) is
/// even, colour_b where it is odd. Linear RGB; evaluated by shading/textures/checker_texture.h.
struct CheckerTexture {
    float size = 1.0f;  ///< edge of one cube, world units (> 0)
    Vec3 color_a{1.0f};
    Vec3 color_b{0.0f};
    Vec3 offset{0.0f};  ///< added to the point first (moves the pattern by -offset)
};

/// An image's mipmap pyramid (Williams 1983, "Pyramidal Parametrics"): level 0 is the image in
/// linear RGB, each next level half the size (rounded down, at least 1) down to 1×1, built by
/// shading/textures/mip_pyramid.h.
struct MipPyramid {
    std::vector<Image> levels;
};

/// How texture coordinates outside [0, 1] are mapped back in.
enum class TextureWrap {
    repeat,  ///< the image tiles the plane (u − floor(u))
    clamp,   ///< the border texels extend outward
};

/// How an image texture is sampled (shading/textures/image_texture.h).
enum class TextureFilter {
    nearest,    ///< the nearest texel of the full-size image (blocky when magnified, aliases)
    bilinear,   ///< the four nearest texels of the full-size image (aliases when minified)
    trilinear,  ///< bilinear in the two mipmap levels around the pixel's footprint, blended
};

/// An image mapped by texture coordinates: (u, v) = (0, 0) is the image's lower-left corner,
/// (1, 1) its upper-right, texel centres at half-integer texel coordinates. Linear RGB (8-bit
/// files are sRGB-decoded when read).
struct ImageTexture {
    std::shared_ptr<const MipPyramid> pyramid;  ///< never null; shared by every use of the file
    std::string file;                           ///< as named where it was referred to
    TextureWrap wrap = TextureWrap::repeat;
    TextureFilter filter = TextureFilter::trilinear;
};

/// Every texture kind. Adding one: its struct here and in this list, its evaluation in
/// shading/textures/, its key in io/scene_json.cpp and docs/scene-format.md.
using Texture = std::variant<CheckerTexture, ImageTexture>;

}  // namespace hikari
