#pragma once
// The per-vertex half of the vertex stage (raster/vertex_pipeline.h), written once for the CPU's
// project_to_screen and the GPU's vertex kernel (raster/zbuffer_kernel.h): p_c = P V p_w, the test
// against the clip volume (raster/clip.h), and for a vertex inside it the perspective divide and
// the viewport.

#include <cstdint>

#include "hikari/core/host_device.h"
#include "hikari/core/mat4.h"
#include "hikari/core/vec.h"
#include "hikari/raster/clip.h"
#include "hikari/raster/screen_triangle.h"
#include "hikari/raster/vertex_pipeline.h"

namespace hikari {

/// Signed distances to the clip planes, ≥ 0 inside: near, then the four guard-band sides.
HIKARI_HD inline float clip_plane_distance(Vec4 p, int plane) {
    switch (plane) {
        case 0:
            return p.z + p.w;
        case 1:
            return k_guard_band * p.w - p.x;
        case 2:
            return k_guard_band * p.w + p.x;
        case 3:
            return k_guard_band * p.w - p.y;
        default:
            return k_guard_band * p.w + p.y;
    }
}

/// inside_clip_volume (raster/clip.h).
HIKARI_HD inline bool in_clip_volume(Vec4 p) {
    for (int plane = 0; plane < 5; ++plane)
        if (!(clip_plane_distance(p, plane) >= 0.0f)) return false;
    return true;
}

/// The perspective divide, then the viewport (pixel centres at +0.5, y down).
HIKARI_HD inline ScreenVertex to_screen(const RasterView& view, Vec4 clip) {
    const Vec3 ndc = clip.xyz() * (1.0f / clip.w);
    const float inv_w = view.orthographic ? 1.5f - 0.5f * ndc.z : 1.0f / clip.w;
    Vec3 screen = transform_point(view.screen_from_clip, ndc);
    // Depth key −near/w rather than NDC z: both are affine across the triangle, but NDC z
    // crowds toward 1 (float spacing 6e-8) when far/near is large.
    screen.z = -view.near_plane * inv_w;
    return {screen, inv_w};
}

/// World point `p` through `view`: its clip position, whether that is inside the clip volume,
/// and then its screen vertex (left as it is otherwise).
HIKARI_HD inline void transform_vertex(const RasterView& view, Vec3 p, Vec4& clip, uint8_t& inside,
                                       ScreenVertex& screen) {
    clip = view.clip_from_world * Vec4(p, 1.0f);
    inside = in_clip_volume(clip) ? 1 : 0;
    if (inside) screen = to_screen(view, clip);
}

}  // namespace hikari
