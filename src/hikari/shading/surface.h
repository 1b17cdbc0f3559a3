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
};

}  // namespace hikari
