#include "hikari/raster/shade_visibility.h"

#include <cmath>

#include "hikari/frame/tiles.h"
#include "hikari/raster/cull.h"
#include "hikari/shading/direct.h"
#include "hikari/shading/material_eval.h"

namespace hikari {

namespace {

struct ShadeContext {
    const Scene& scene;
    const TriangleSet& tris;
    Interpolation interp;
    LightingEnvironment lighting;
};

/// The material at `p` (its texture applied) lit by every light: the raster methods draw no
/// shadows yet, so every light that faces the point reaches it.
Vec3 shade_point(const ShadeContext& ctx, uint32_t material, Vec3 p, Vec3 n, Vec3 to_eye) {
    SurfacePoint<float> s;
    s.position = p;
    s.normal = n;
    s.geometric_normal = n;
    s.to_eye = to_eye;
    const MaterialSample<float> m =
        evaluate_material<float>(ctx.scene.materials.data(), static_cast<int32_t>(material), s);
    const auto lit = [](size_t, const LightSample&, const SurfacePoint<float>&, bool) {
        return true;
    };
    return direct_lighting<float>(ctx.lighting, s, m, true, lit).colour;
}

/// `n` turned to the side of `ng_front` (the face normal facing the viewer), as the ray tracer
/// does: a normal interpolated to face away falls back to the face normal.
Vec3 facing(Vec3 n, bool entering, Vec3 ng_front, Vec3 view_dir) {
    const float len2 = dot(n, n);
    if (!(len2 > 0.0f)) return ng_front;
    n = (entering ? n : -n) / std::sqrt(len2);
    return dot(n, view_dir) > 0.0f ? ng_front : n;
}

}  // namespace

bool perspective_barycentrics(Vec4 c0, Vec4 c1, Vec4 c2, double ndc_x, double ndc_y,
                              std::array<float, 3>& weights) {
    // Columns (x, y, w) of the three vertices; Cramer's rule gives λ_i ∝ q · (col_j × col_k).
    const double col[3][3] = {{c0.x, c0.y, c0.w}, {c1.x, c1.y, c1.w}, {c2.x, c2.y, c2.w}};
    const double q[3] = {ndc_x, ndc_y, 1.0};
    double l[3], sum = 0;
    for (int i = 0; i < 3; ++i) {
        const double* a = col[(i + 1) % 3];
        const double* b = col[(i + 2) % 3];
        l[i] = q[0] * (a[1] * b[2] - a[2] * b[1]) + q[1] * (a[2] * b[0] - a[0] * b[2]) +
               q[2] * (a[0] * b[1] - a[1] * b[0]);
        sum += l[i];
    }
    if (!(std::abs(sum) > 0.0) || !std::isfinite(sum)) return false;
    for (int i = 0; i < 3; ++i) weights[i] = static_cast<float>(l[i] / sum);
    return true;
}

Framebuffer shade_visibility(const Scene& scene, const ProjectedScene& ps,
                             const VisibilityBuffer& vis, const RenderSettings& settings) {
    const int width = vis.width, height = vis.height;
    Framebuffer fb(width, height, scene.background);
    const ShadeContext ctx{scene,
                           ps.scene.triangles,
                           settings.interp,
                           {scene.lights.data(), scene.lights.size(), scene.ambient}};
    const CameraFrame frame = make_camera_frame(scene.camera);
    const Vec3 eye = scene.camera.eye;

    for_each_tile(width, height, settings.control, [&](const Tile& tile) {
        for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x) {
                const size_t pixel = static_cast<size_t>(y) * width + x;
                const uint32_t t = vis.triangle[pixel];
                if (t == k_no_triangle) continue;
                const uint32_t src = ps.triangles[t].source;
                const auto& idx = ctx.tris.indices[src];
                const Vec3 p0 = ctx.tris.positions[idx[0]], p1 = ctx.tris.positions[idx[1]],
                           p2 = ctx.tris.positions[idx[2]];

                // Perspective-correct weights of the pixel centre on the source triangle.
                const double ndc_x = 2.0 * (x + 0.5) / width - 1.0;
                const double ndc_y = 1.0 - 2.0 * (y + 0.5) / height;
                std::array<float, 3> b{1.0f / 3, 1.0f / 3, 1.0f / 3};
                perspective_barycentrics(ps.clip_positions[idx[0]], ps.clip_positions[idx[1]],
                                         ps.clip_positions[idx[2]], ndc_x, ndc_y, b);
                const Vec3 p = b[0] * p0 + b[1] * p1 + b[2] * p2;
                const Vec3 n0 = ctx.tris.normals[idx[0]], n1 = ctx.tris.normals[idx[1]],
                           n2 = ctx.tris.normals[idx[2]];
                const Vec3 n_interp = b[0] * n0 + b[1] * n1 + b[2] * n2;
                const Vec3 dir = camera_ray(frame, x + 0.5f, y + 0.5f).direction;

                // Two-sided, as in the ray tracer: the side the eye sees is the front.
                Vec3 ng = face_normal(p0, p1, p2);
                const float ng_len = length(ng);
                ng = ng_len > 0.0f ? ng / ng_len : -dir;
                const bool entering = dot(ng, dir) < 0.0f;
                const Vec3 ng_front = entering ? ng : -ng;
                const uint32_t m = ctx.tris.material[src];

                Vec3 colour;
                switch (ctx.interp) {
                    case Interpolation::flat: {  // one colour per polygon, at its centroid
                        const Vec3 c = (p0 + p1 + p2) / 3.0f;
                        colour = shade_point(ctx, m, c, ng_front, normalize(eye - c));
                        break;
                    }
                    case Interpolation::gouraud: {  // shade the vertices, blend the colours
                        const Vec3 ps3[3] = {p0, p1, p2};
                        const Vec3 ns3[3] = {n0, n1, n2};
                        colour = Vec3(0.0f);
                        for (int k = 0; k < 3; ++k) {
                            const Vec3 to_eye = normalize(eye - ps3[k]);
                            const Vec3 nk = facing(ns3[k], entering, ng_front, -to_eye);
                            colour += b[k] * shade_point(ctx, m, ps3[k], nk, to_eye);
                        }
                        break;
                    }
                    case Interpolation::phong:  // interpolate the normal, shade the pixel
                        colour =
                            shade_point(ctx, m, p, facing(n_interp, entering, ng_front, dir), -dir);
                        break;
                }
                fb.color.pixels[pixel] = colour;
                fb.depth[pixel] = length(p - eye);
                fb.id[pixel] = ctx.tris.id[src] + 1;
                const float nl = length(n_interp);
                const Vec3 sn = nl > 0.0f ? n_interp / nl : ng;
                fb.normal[pixel] = dot(sn, dir) < 0.0f ? sn : -sn;
            }
    });
    return fb;
}

}  // namespace hikari
