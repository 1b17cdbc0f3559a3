#pragma once
// Ray cones (Akenine-Möller, Nilsson, Andersson, Barré-Brisebois, Toth & Karras, "Texture Level
// of Detail Strategies for Real-Time Ray Tracing", Ray Tracing Gems 2019, ch. 20): each ray
// carries a cone whose width at distance t is width + spread·t. A camera ray's cone covers one
// pixel (spread = the pixel's angle); mirrors and refracting surfaces pass the width on and bend
// the spread by the surface's curvature. At a hit, the cone's cross-section, stretched by
// 1/|cos θ| along the plane of incidence, mapped through the surface's UV gradients, is the
// pixel's footprint in texture space: what picks a texture's mipmap level, as screen-space
// derivatives do in the rasterizer.

#include <algorithm>
#include <array>
#include <cmath>

#include "hikari/core/vec.h"
#include "hikari/geometry/surface_uv.h"
#include "hikari/scene/camera.h"

namespace hikari {

/// A ray's cone: full width at the ray's origin (world units, negative past a focus) and spread
/// angle (radians, full angle; negative: converging).
struct RayCone {
    float width = 0.0f;
    float spread = 0.0f;

    /// The cone's width at distance `t` along its ray.
    HIKARI_HD float width_at(float t) const { return width + spread * t; }
};

/// The angle one pixel subtends at the eye: α = atan(2 tan(fov_y / 2) / height) (RTG ch. 20,
/// eq. 20.30).
inline float pixel_spread_angle(const Camera& camera) {
    const float tan_half = std::tan(camera.fov_y_degrees * 3.14159265358979f / 360.0f);
    return std::atan(2.0f * tan_half / static_cast<float>(camera.height));
}

/// The cones of the camera's rays: one pixel's angle at the image centre, `spread_on_axis`
/// (pixel_spread_angle), which a ray at angle θ off the view axis sees shrunk by cos θ (the
/// pixel is seen obliquely and from farther away), so that the width at view depth z is
/// spread_on_axis·z everywhere, the size of a pixel on a plane facing the camera at that depth.
/// An orthographic camera's rays are cylinders: one pixel wide (view_height / height) at any
/// distance, spread 0.
struct CameraCones {
    Vec3 forward;          ///< unit view direction
    float spread_on_axis;  ///< radians; 0 for an orthographic camera
    float pixel_width;     ///< the width of an orthographic camera's rays; 0 for a pinhole

    explicit CameraCones(const Camera& camera)
        : forward(normalize(camera.look_at - camera.eye)),
          spread_on_axis(
              camera.projection == Projection::orthographic ? 0.0f : pixel_spread_angle(camera)),
          pixel_width(camera.projection == Projection::orthographic
                          ? camera.view_height / static_cast<float>(camera.height)
                          : 0.0f) {}

    /// The cone of the camera ray along unit `direction`.
    HIKARI_HD RayCone operator()(Vec3 direction) const {
        return {pixel_width, spread_on_axis * std::max(dot(direction, forward), 0.0f)};
    }
};

/// The mean curvature of a smooth-shaded triangle as its vertex normals describe it: along each
/// edge, how fast the normal turns per unit length, (n_j − n_i)·(p_j − p_i) / |p_j − p_i|², the
/// mean of the three edges. 1/r on any triangle of a sphere of radius r whose normals point out;
/// 0 with flat normals. Positive where the surface bulges toward the normals' side.
HIKARI_HD inline float triangle_curvature(const std::array<Vec3, 3>& p,
                                          const std::array<Vec3, 3>& n) {
    float sum = 0.0f;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        const Vec3 e = p[j] - p[i];
        const float e2 = dot(e, e);
        if (e2 > 0.0f) sum += dot(n[j] - n[i], e) / e2;
    }
    return sum / 3.0f;
}

/// The cone of the mirror ray at a hit where the incoming cone has width `width`, on a surface
/// of signed curvature `curvature` (1/radius: positive where it bulges toward the ray, as a
/// sphere seen from outside; 0 for planes and flat triangles). The normal turns by curvature·width
/// across the footprint and the mirror direction by twice that: spread' = spread + 2·κ·width
/// (RTG ch. 20's β, from the curvature rather than from G-buffer normals).
HIKARI_HD inline RayCone reflected_cone(const RayCone& incoming, float width, float curvature) {
    return {width, incoming.spread + 2.0f * curvature * width};
}

/// The cone of the refracted ray at such a hit, for the relative index `eta` = n_in / n_out and
/// the cosines of the incident and refracted angles to the normal: small angles scale by
/// dθ_t/dθ_i = η cos θ_i / cos θ_t (Snell's law, differentiated), and the normal's turn across
/// the footprint (curvature·width) turns the refracted ray by (η cos θ_i − cos θ_t) times it:
/// a glass sphere (η < 1 entering) focuses.
HIKARI_HD inline RayCone refracted_cone(const RayCone& incoming, float width, float curvature,
                                        float eta, float cos_in, float cos_out) {
    const float cos_t = std::max(cos_out, 1e-4f);
    return {width,
            incoming.spread * eta * cos_in / cos_t + (eta * cos_in - cos_out) * curvature * width};
}

/// A footprint in texture space: how far (u, v) moves across it along two directions (the
/// SurfacePoint fields du_dx, dv_dx and du_dy, dv_dy).
struct UvFootprint {
    float du_dx = 0, dv_dx = 0, du_dy = 0, dv_dy = 0;
    Vec3 dp_dx{0.0f}, dp_dy{0.0f};  ///< the same two axes in world space (SurfacePoint's)
};

/// The texture-space footprint of a cone of width `width` meeting a surface with unit normal
/// `normal` along unit `direction`, with the surface's UV gradients `uv`: the cone's section is
/// an ellipse with axes |width| across the plane of incidence and |width| / |cos θ| along it
/// (RTG ch. 20's 1/|n·d| term, kept anisotropic); each axis goes through the gradients. The
/// first axis (the "x" fields) is the long one. Grazing angles are capped at |cos θ| = 10⁻⁴.
HIKARI_HD inline UvFootprint cone_footprint(float width, Vec3 direction, Vec3 normal,
                                            const SurfaceUv& uv) {
    const float w = std::abs(width);
    const float cos_theta = dot(direction, normal);
    const float stretch = 1.0f / std::max(std::abs(cos_theta), 1e-4f);
    // The long axis: the ray's direction projected onto the tangent plane.
    Vec3 along = direction - cos_theta * normal;
    const float along_length = length(along);
    if (along_length > 1e-6f) {
        along = along / along_length;
    } else {
        // Head on: any tangent will do.
        const Vec3 a = std::abs(normal.x) < 0.9f ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
        along = normalize(cross(a, normal));
    }
    const Vec3 across = cross(normal, along);
    const Vec3 long_axis = along * (w * stretch), short_axis = across * w;
    return {dot(uv.du_dp, long_axis),
            dot(uv.dv_dp, long_axis),
            dot(uv.du_dp, short_axis),
            dot(uv.dv_dp, short_axis),
            long_axis,
            short_axis};
}

}  // namespace hikari
