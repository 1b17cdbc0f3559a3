#pragma once
// What the deferred shading pass works out at a pixel centre from the triangle seen there,
// written once for the CPU pass (raster/shade_visibility.cpp) and the GPU's shading kernel
// (raster/zbuffer_kernel.h): perspective-correct weights from clip space (Olano & Greer 1997),
// texture coordinates and their pixel derivatives (Heckbert 1989), the point's steps per pixel
// on its tangent plane, and the normal turned toward the eye as the ray tracer turns it.

#include <array>
#include <cmath>

#include "hikari/core/host_device.h"
#include "hikari/core/ray.h"
#include "hikari/core/vec.h"
#include "hikari/scene/camera.h"
#include "hikari/shading/surface.h"

namespace hikari {

/// The planes of a triangle's perspective-correct weights (barycentric_planes).
using BarycentricPlanes = std::array<std::array<double, 3>, 3>;

/// The vectors k_i = col_j × col_k of the columns (x, y, w) of the three clip-space corners:
/// Cramer's rule gives the point projecting to q = (ndc_x, ndc_y, 1) the weights λ_i ∝ q · k_i.
HIKARI_HD inline BarycentricPlanes barycentric_planes(Vec4 c0, Vec4 c1, Vec4 c2) {
    const double col[3][3] = {{c0.x, c0.y, c0.w}, {c1.x, c1.y, c1.w}, {c2.x, c2.y, c2.w}};
    BarycentricPlanes k{};
    for (int i = 0; i < 3; ++i) {
        const double* a = col[(i + 1) % 3];
        const double* b = col[(i + 2) % 3];
        k[i] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }
    return k;
}

HIKARI_HD inline double dot3(const std::array<double, 3>& a, const double (&q)[3]) {
    return a[0] * q[0] + a[1] * q[1] + a[2] * q[2];
}

/// The weights λ_i = q·k_i / Σ q·k_j at q = (ndc_x, ndc_y, 1) (perspective_barycentrics); false
/// (weights untouched) for a triangle seen edge-on.
HIKARI_HD inline bool barycentric_weights(const BarycentricPlanes& k, double ndc_x, double ndc_y,
                                          std::array<float, 3>& weights) {
    const double q[3] = {ndc_x, ndc_y, 1.0};
    double l[3], sum = 0;
    for (int i = 0; i < 3; ++i) {
        l[i] = dot3(k[i], q);
        sum += l[i];
    }
    if (!(std::abs(sum) > 0.0) || !std::isfinite(sum)) return false;
    for (int i = 0; i < 3; ++i) weights[i] = static_cast<float>(l[i] / sum);
    return true;
}

/// Texture coordinates at a pixel and how far they move per pixel step: what picks a texture's
/// mipmap level (SurfacePoint::du_dx and the others).
struct PixelUv {
    Vec2 uv;
    float du_dx = 0, dv_dx = 0;  ///< per step to the right (x + 1)
    float du_dy = 0, dv_dy = 0;  ///< per step down (y + 1, rows counted from the top)
    /// The surface point's world-space steps along x and y (SurfacePoint::dp_dx, dp_dy).
    Vec3 dp_dx{0.0f}, dp_dy{0.0f};
};

/// The surface point a raster pixel shades (shading/surface.h): at `point` with normal `n`
/// (also its geometric normal), seen along `to_eye`, its texture coordinates and their steps from
/// `tex`, and the interpolated vertex colour.
HIKARI_HD inline SurfacePoint<float> pixel_surface_point(Vec3 point, Vec3 n, Vec3 to_eye,
                                                         const PixelUv& tex, Vec3 vertex_colour) {
    SurfacePoint<float> s;
    s.position = point;
    s.normal = n;
    s.geometric_normal = n;
    s.to_eye = to_eye;
    s.u = tex.uv.x, s.v = tex.uv.y;
    s.du_dx = tex.du_dx, s.dv_dx = tex.dv_dx, s.du_dy = tex.du_dy, s.dv_dy = tex.dv_dy;
    s.dp_dx = tex.dp_dx, s.dp_dy = tex.dp_dy;
    s.vertex_colour = vertex_colour;
    return s;
}

/// The perspective-correct (u, v) of the point of the clip-space triangle `clip` with corner
/// coordinates `uv` that projects to NDC (ndc_x, ndc_y), and its exact derivatives along the
/// pixel grid of a `width` × `height` image. With q = (ndc_x, ndc_y, 1) and the weights
/// λ_i = q·k_i / q·K of perspective_barycentrics, u = q·U / q·K for U = Σ u_i k_i, a ratio of
/// two functions affine in screen space, so ∂u/∂ndc_x = (U_x − u K_x) / q·K, then ×2/width per
/// pixel (and ×(−2/height) along y, which grows downward). Heckbert 1989 ("Fundamentals of
/// Texture Mapping and Image Warping", §3.5.5) derives the same Jacobian. All zero for a triangle
/// seen edge-on.
HIKARI_HD inline PixelUv perspective_uv(const std::array<Vec4, 3>& clip,
                                        const std::array<Vec2, 3>& uv, double ndc_x, double ndc_y,
                                        int width, int height) {
    const BarycentricPlanes k = barycentric_planes(clip[0], clip[1], clip[2]);
    const double q[3] = {ndc_x, ndc_y, 1.0};
    std::array<double, 3> big_k{}, big_u{}, big_v{};
    for (int i = 0; i < 3; ++i)
        for (int a = 0; a < 3; ++a) {
            big_k[a] += k[i][a];
            big_u[a] += uv[i].x * k[i][a];
            big_v[a] += uv[i].y * k[i][a];
        }
    const double sum = dot3(big_k, q);
    PixelUv out;
    if (!(std::abs(sum) > 0.0) || !std::isfinite(sum)) return out;
    const double u = dot3(big_u, q) / sum, v = dot3(big_v, q) / sum;
    const double per_x = 2.0 / width / sum, per_y = -2.0 / height / sum;
    out.uv = {static_cast<float>(u), static_cast<float>(v)};
    out.du_dx = static_cast<float>((big_u[0] - u * big_k[0]) * per_x);
    out.dv_dx = static_cast<float>((big_v[0] - v * big_k[0]) * per_x);
    out.du_dy = static_cast<float>((big_u[1] - u * big_k[1]) * per_y);
    out.dv_dy = static_cast<float>((big_v[1] - v * big_k[1]) * per_y);
    return out;
}

/// `n` turned to the side of `ng_front` (the face normal facing the viewer), as the ray tracer
/// does: a normal interpolated to face away falls back to the face normal.
HIKARI_HD inline Vec3 facing(Vec3 n, bool entering, Vec3 ng_front, Vec3 view_dir) {
    const float len2 = dot(n, n);
    if (!(len2 > 0.0f)) return ng_front;
    n = (entering ? n : -n) / std::sqrt(len2);
    return dot(n, view_dir) > 0.0f ? ng_front : n;
}

/// Where the camera ray of pixel (x + dx, y + dy) meets the plane through `p` with normal `n`,
/// less p: the point's step per pixel on the surface (0 where that ray runs along the plane).
HIKARI_HD inline Vec3 tangent_plane_step(const CameraFrame& frame, Vec3 p, Vec3 n, int x, int y,
                                         int dx, int dy) {
    const Ray r = camera_ray(frame, x + dx + 0.5f, y + dy + 0.5f);
    const float denominator = dot(n, r.direction);
    if (denominator == 0.0f) return Vec3(0.0f);
    const Vec3 step = r.at(dot(p - r.origin, n) / denominator) - p;
    return std::isfinite(step.x + step.y + step.z) ? step : Vec3(0.0f);
}

}  // namespace hikari
