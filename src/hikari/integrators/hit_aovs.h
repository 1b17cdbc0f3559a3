#pragma once
// The AOVs a ray-traced pixel records from the hit of the ray through its centre (shared by the
// Whitted ray tracer and the path tracer).

#include "hikari/bvh/scene_intersector.h"
#include "hikari/frame/framebuffer.h"

namespace hikari {

/// Pixel i's depth (distance along the unit centre ray `direction`), primitive id and normal
/// turned toward the eye, from the centre ray's hit `first`.
inline void store_hit_aovs(Framebuffer& fb, size_t i, Vec3 direction, const SurfaceHit& first) {
    fb.depth[i] = first.t;
    fb.id[i] = first.id + 1;
    fb.normal[i] =
        dot(first.shading_normal, direction) < 0.0f ? first.shading_normal : -first.shading_normal;
}

}  // namespace hikari
