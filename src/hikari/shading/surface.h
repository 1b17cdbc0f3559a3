#pragma once
// A surface point as shading sees it, for one point or for each lane of a pack.

#include "hikari/core/lanes.h"
#include "hikari/core/vec.h"

namespace hikari {

/// Where light is reflected toward the eye. Normals are unit length, world space and turned to
/// the side the eye sees.
template <class F>
struct SurfacePoint {
    Vec3T<F> position;           ///< world space
    Vec3T<F> normal;             ///< shading normal (interpolated for meshes), facing the eye
    Vec3T<F> geometric_normal;   ///< the true surface normal, facing the eye
    Vec3T<F> to_eye;             ///< unit direction from the point toward the eye (V)
    F u = F(0.0f), v = F(0.0f);  ///< texture coordinates (0 where the surface has none)
    /// How far (u, v) moves per pixel step along the image's x and y: the pixel's footprint in
    /// texture space, which picks the mipmap level. The rasterizer takes screen-space
    /// derivatives; the ray tracer a ray cone's width (isotropic: du_dx = dv_dy, the others 0).
    /// All 0: sample the finest level.
    F du_dx = F(0.0f), dv_dx = F(0.0f), du_dy = F(0.0f), dv_dy = F(0.0f);
    /// The same footprint in world space: how far the point moves per pixel step along two
    /// directions on the surface (the ray tracer: the cone's long and short axes), what a solid
    /// texture (the checker) is box-filtered over. 0: a point, no filtering.
    Vec3T<F> dp_dx = Vec3T<F>(F(0.0f)), dp_dy = Vec3T<F>(F(0.0f));
    /// The vertex colour interpolated at the point (white where the mesh has none); a material
    /// with vertex_colours multiplies ka and kd by it.
    Vec3T<F> vertex_colour = Vec3T<F>(F(1.0f));
};

}  // namespace hikari
