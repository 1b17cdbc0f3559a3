#pragma once
// An image texture at a surface point: texels fetched by (u, v), filtered over the pixel's
// footprint through the mipmap pyramid (Williams 1983).

#include "hikari/core/image.h"
#include "hikari/core/lanes.h"
#include "hikari/scene/texture.h"
#include "hikari/shading/surface.h"
#include "hikari/shading/textures/lane_form.h"

namespace hikari {

/// The texel index `i` brought inside [0, size) by `wrap`.
int wrap_texel(int i, int size, TextureWrap wrap);

/// The colour of `level` at texture coordinates (u, v): the nearest texel, or the bilinear blend
/// of the four around it. Texel (x, y) of an image (row 0 at the top) has its centre at
/// u = (x + 0.5) / width, v = 1 − (y + 0.5) / height.
Vec3 sample_nearest(const Image& level, float u, float v, TextureWrap wrap);
Vec3 sample_bilinear(const Image& level, float u, float v, TextureWrap wrap);

/// The mipmap level of detail for a pixel footprint given as the UV derivatives along screen x
/// and y: log2 of the longer footprint axis measured in texels of level 0 (the OpenGL formula,
/// isotropic), clamped to [0, levels − 1]. 0 for a zero footprint.
float mip_level_of_detail(const MipPyramid& pyramid, float du_dx, float dv_dx, float du_dy,
                          float dv_dy);

/// The texture's colour at (u, v) with the given footprint, by the texture's filter: nearest or
/// bilinear in level 0, or trilinear (bilinear in the two levels around the level of detail,
/// blended linearly).
Vec3 sample_image_texture(const ImageTexture& texture, float u, float v, float du_dx, float dv_dx,
                          float du_dy, float dv_dy);

/// The texture's colour at `point`, one point at a time: lanes meeting an image texture are
/// shaded by the scalar code (no lane form).
template <class F>
Vec3T<F> texture_colour(const ImageTexture& t, const SurfacePoint<F>& point) {
    static_assert(k_is_scalar<F>, "image textures have no lane form");
    return sample_image_texture(t, point.u, point.v, point.du_dx, point.dv_dx, point.du_dy,
                                point.dv_dy);
}

}  // namespace hikari
