#pragma once
// What a nearest-hit query answers about the surface it found (every intersector: the CPU's
// SceneIntersector and the flat one the GPU kernels share, bvh/flat_intersector.h).

#include <cstdint>

#include "hikari/core/ray.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// Which kind of primitive a nearest-hit search found.
enum class HitKind : uint8_t { none, triangle, sphere, plane };

/// Where a ray meets a surface, with what the shading of that point needs.
struct SurfaceHit {
    float t = k_infinity;   ///< distance along the ray
    Vec3 position;          ///< world space
    Vec3 geometric_normal;  ///< unit, as the primitive defines it (not flipped)
    Vec3 shading_normal;    ///< unit, interpolated for meshes; same side as geometric
    uint32_t material = 0;  ///< index into Scene::materials
    PrimitiveId id = 0;     ///< the primitive hit
    HitKind kind = HitKind::none;
    uint32_t index = 0;            ///< into Scene::triangles, spheres or planes, by `kind`
    float bary_u = 0, bary_v = 0;  ///< triangles: the weights of corners 1 and 2
};

}  // namespace hikari
