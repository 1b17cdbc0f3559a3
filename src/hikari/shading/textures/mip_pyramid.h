#pragma once
// Building an image texture's mipmap pyramid once, when the texture is loaded.

#include "hikari/core/image.h"
#include "hikari/scene/texture.h"

namespace hikari {

/// The size of the level below one of `size` texels along an axis: half, rounded down, at
/// least 1 (as OpenGL sizes the levels of a non-power-of-two texture).
int next_mip_size(int size);

/// `image` shrunk to `width` × `height` (each no larger than the image's) by an exact box filter:
/// every output texel is the area-weighted mean of the input texels it covers, fractions of
/// texels included. For a halving of an even size that is the 2×2 mean; an odd size is not
/// rounded to even first, so no texel is dropped or counted twice and the mean colour of the
/// image is kept exactly (in exact arithmetic) at every level.
Image box_downsample(const Image& image, int width, int height);

/// The pyramid of `base` (linear RGB, at least 1×1): level 0 is `base` with non-finite texels
/// set to 0, each next level
/// box_downsample()d to next_mip_size() of the last, down to 1×1.
MipPyramid build_mip_pyramid(Image base);

}  // namespace hikari
