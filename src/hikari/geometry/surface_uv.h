#pragma once
// Texture coordinates of the analytic primitives and of triangles, and how fast they change
// across the surface: the one definition that the ray tracer (at its hits) and the rasterizer
// (at its tessellation's vertices) both use, so a texture lands on the same spot in every method.
// Conventions (docs/scene-format.md, "Texture coordinates"): (0, 0) is the image's lower-left
// corner, (1, 1) its upper-right.

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "hikari/core/vec.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// (u, v) at a surface point and their gradients along the surface: for a small step a in the
/// tangent plane, u changes by dot(du_dp, a) and v by dot(dv_dp, a). A texture's footprint is
/// a world-space footprint mapped through these.
struct SurfaceUv {
    Vec2 uv;
    Vec3 du_dp{0.0f};  ///< world units⁻¹
    Vec3 dv_dp{0.0f};
};

/// The sphere's longitude/latitude mapping at point `p` on it (y is the pole axis): with
/// d = (p − centre) / radius, u = 1/2 + atan2(d.x, d.z) / 2π (u grows eastward, i.e. to the right
/// seen from outside; the seam u = 0 ≡ 1 faces −z, away from a camera looking down −z) and
/// v = 1/2 + asin(d.y) / π (0 at the south pole, 1 at the north pole). At the poles, where u is
/// undefined, the gradients are capped.
HIKARI_HD inline SurfaceUv sphere_uv(const Sphere& s, Vec3 p) {
    constexpr float k_pi = std::numbers::pi_v<float>;
    const Vec3 d = (p - s.center) / s.radius;
    const float dy = std::clamp(d.y, -1.0f, 1.0f);
    SurfaceUv out;
    out.uv.x = 0.5f + std::atan2(d.x, d.z) / (2.0f * k_pi);
    out.uv.y = 0.5f + std::asin(dy) / k_pi;
    // u depends on the azimuth ψ = atan2(d.x, d.z): dψ = (d.z dd.x − d.x dd.z) / (d.x² + d.z²).
    const float ring2 = std::max(d.x * d.x + d.z * d.z, 1e-8f);
    out.du_dp = Vec3(d.z, 0.0f, -d.x) / (2.0f * k_pi * s.radius * ring2);
    out.dv_dp = Vec3(0.0f, 1.0f, 0.0f) / (k_pi * s.radius * std::sqrt(ring2));
    return out;
}

/// The plane's texture axes (unit, in the plane, (u_axis, v_axis, normal) right-handed): u_axis
/// is world x projected onto the plane, or y × normal for planes facing (nearly) ±x, so a floor
/// (normal +y) has u along +x and v along −z, a wall facing +z has u along +x and v along +y.
HIKARI_HD inline std::array<Vec3, 2> plane_uv_axes(const Plane& plane) {
    const Vec3 n = plane.normal;
    Vec3 u = Vec3(1.0f, 0.0f, 0.0f) - n.x * n;
    if (dot(u, u) < 1e-6f) u = cross(Vec3(0.0f, 1.0f, 0.0f), n);
    u = normalize(u);
    return {u, cross(n, u)};
}

/// The plane's planar mapping at point `p`: (u, v) = ((p − point)·u_axis, (p − point)·v_axis) /
/// uv_scale, so the texture repeats every uv_scale world units and (0, 0) sits at `point`.
HIKARI_HD inline SurfaceUv plane_uv(const Plane& plane, Vec3 p) {
    const auto [u_axis, v_axis] = plane_uv_axes(plane);
    const Vec3 q = p - plane.point;
    const float inverse_scale = 1.0f / plane.uv_scale;
    return {{dot(q, u_axis) * inverse_scale, dot(q, v_axis) * inverse_scale},
            u_axis * inverse_scale,
            v_axis * inverse_scale};
}

/// The gradients of (u, v) over the triangle (p0, p1, p2) with corner coordinates (t0, t1, t2),
/// in the triangle's plane: the solution of du_dp·e_k = Δu_k for its edges e_k. Zero for a
/// degenerate triangle or mapping.
HIKARI_HD inline SurfaceUv triangle_uv_gradients(const std::array<Vec3, 3>& p,
                                                 const std::array<Vec2, 3>& t) {
    const Vec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
    const Vec3 n = cross(e1, e2);
    const float n2 = dot(n, n);
    SurfaceUv out;
    if (!(n2 > 0.0f)) return out;
    // The gradient of a function linear over the triangle with differences (f1, f2) along
    // (e1, e2) is (f1 (e2 × n) + f2 (n × e1)) / |n|².
    const Vec3 g1 = cross(e2, n) / n2, g2 = cross(n, e1) / n2;
    out.du_dp = (t[1].x - t[0].x) * g1 + (t[2].x - t[0].x) * g2;
    out.dv_dp = (t[1].y - t[0].y) * g1 + (t[2].y - t[0].y) * g2;
    return out;
}

}  // namespace hikari
