#include "hikari/raster/vertex_pipeline.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "hikari/core/aabb.h"
#include "hikari/core/parallel.h"
#include "hikari/raster/clip.h"
#include "hikari/raster/cull.h"
#include "hikari/raster/tessellate.h"
#include "hikari/raster/vertex_transform.h"

namespace hikari {

namespace {

/// The smallest view depth (distance along the view axis) of the points of `plane` that the
/// view frustum of `frame` shows, or infinity where it shows none. Over the image, 1/depth of a
/// plane is affine in the image coordinates (why perspective-correct interpolation works), so
/// its largest value, the nearest point, is at a corner of the image: the corner ray
/// eye + s·d meets the plane at s = −h / (n·d), h the eye's height above it.
float nearest_visible_depth(const Plane& plane, const CameraFrame& frame) {
    const float h = dot(plane.normal, frame.eye - plane.point);
    if (h == 0.0f) return 0.0f;
    float most = 0.0f;  // the largest 1/depth over the corners
    for (const float x : {-1.0f, 1.0f})
        for (const float y : {-1.0f, 1.0f}) {
            const Vec3 d = frame.forward + (x * frame.tan_half_fov_y * frame.aspect) * frame.right +
                           (y * frame.tan_half_fov_y) * frame.up;
            most = std::max(most, -dot(plane.normal, d) / h);
        }
    return most > 0.0f ? 1.0f / most : k_infinity;
}

bool finite(Vec4 p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
}

/// What the vertex stage did with a triangle (for --stats).
enum Fate : uint8_t { k_kept, k_cut, k_clipped_away, k_culled, k_not_finite };

/// Clips triangle t and writes its screen-space pieces to `out` (when not null); returns how
/// many pieces there are, and in `fate` what happened to it. A triangle whose corners are all
/// inside the clip volume (most) takes its corners' screen vertices as they are.
int project_one(const TriangleSet& tris, const RasterView& view, const ScreenProjection& sp,
                uint32_t t, bool cull, ScreenTriangle* out, uint8_t& fate) {
    const auto& idx = tris.indices[t];
    fate = k_culled;
    if (cull && is_back_facing(view, tris, t)) return 0;
    if (sp.vertex_inside[idx[0]] && sp.vertex_inside[idx[1]] && sp.vertex_inside[idx[2]]) {
        fate = k_kept;
        if (out)
            *out = IndexedScreenTriangles{sp.screen.data(), tris.indices.data(), tris.size()}[t];
        return 1;
    }
    const Vec4 a = sp.clip_positions[idx[0]], b = sp.clip_positions[idx[1]],
               c = sp.clip_positions[idx[2]];
    fate = k_not_finite;
    if (!finite(a) || !finite(b) || !finite(c)) return 0;
    const ClipPolygon poly = clip_triangle(a, b, c);
    fate = k_clipped_away;
    if (poly.count < 3) return 0;
    fate = k_cut;
    if (out) {
        std::array<ScreenVertex, k_max_clip_vertices> sv;
        for (int i = 0; i < poly.count; ++i) sv[i] = to_screen(view, poly.v[i]);
        for (int i = 1; i + 1 < poly.count; ++i) out[i - 1] = {{sv[0], sv[i], sv[i + 1]}, t};
    }
    return poly.count - 2;
}

}  // namespace

RasterView make_raster_view(const Camera& camera, const RasterScene& scene, Vec2 sample_offset) {
    RasterView v;
    v.eye = camera.eye;
    v.width = camera.width;
    v.height = camera.height;
    v.sample_offset = sample_offset;
    Aabb bounds;
    for (const Vec3& p : scene.triangles.positions) bounds.extend(p);
    for (const Sphere& s : scene.spheres) {
        bounds.extend(s.center - Vec3(s.radius));
        bounds.extend(s.center + Vec3(s.radius));
    }
    float far_dist = 1.0f;
    if (!bounds.empty())
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3 p{(corner & 1) ? bounds.max.x : bounds.min.x,
                         (corner & 2) ? bounds.max.y : bounds.min.y,
                         (corner & 4) ? bounds.max.z : bounds.min.z};
            far_dist = std::max(far_dist, length(p - camera.eye));
        }
    v.far_plane = 1.01f * far_dist;
    v.view_from_world = view_matrix(camera);
    // Sampling at centre + offset is the image moved by −offset under fixed pixel centres.
    v.screen_from_clip = translate(Vec3(-sample_offset.x, -sample_offset.y, 0.0f)) *
                         viewport(camera.width, camera.height);
    const float aspect = static_cast<float>(camera.width) / static_cast<float>(camera.height);
    if (camera.projection == Projection::orthographic) {
        // Parallel rays from the plane through the eye (scene/camera.h): everything in front of
        // that plane is seen, up to the far plane. The depth key is 1.5 − 0.5 z_ndc (RasterView).
        const float half_h = 0.5f * camera.view_height, half_w = half_h * aspect;
        v.orthographic = true;
        v.forward = normalize(camera.look_at - camera.eye);
        v.near_plane = 1.0f;  // the depth key's scale, as for the shadow maps' parallel views
        v.clip_from_view = orthographic(-half_w, half_w, -half_h, half_h, 0.0f, v.far_plane);
        v.clip_from_world = v.clip_from_view * v.view_from_world;
        return v;
    }
    // A point at distance d inside the frustum has view depth at least d cos(half diagonal).
    const float tan_half_y = std::tan(camera.fov_y_degrees * std::numbers::pi_v<float> / 360.0f);
    const float cos_half_diag =
        1.0f / std::sqrt(1.0f + tan_half_y * tan_half_y * (1 + aspect * aspect));
    // Near: just in front of the nearest geometry the view can show. For meshes and spheres the
    // distance d to the nearest one (a point at d is at least d cos(half diagonal) deep); for an
    // infinite plane its exact nearest visible depth. Planes are tessellated out to 10⁴ times the
    // scene, so a near plane derived from the far one would cut the floor under a low camera away.
    float nearest = scene.nearest_object * cos_half_diag;
    const CameraFrame frame = make_camera_frame(camera);
    for (const Plane& plane : scene.planes)
        nearest = std::min(nearest, nearest_visible_depth(plane, frame));
    // Nothing in front, or the eye on a surface: a sliver of the far distance.
    v.near_plane = std::isfinite(nearest) && nearest > 0.0f ? 0.9f * nearest : 1e-6f * v.far_plane;
    v.clip_from_view = perspective(camera.fov_y_degrees, aspect, v.near_plane, v.far_plane);
    v.clip_from_world = v.clip_from_view * v.view_from_world;
    return v;
}

void project_to_screen(const TriangleSet& tris, const RasterView& view, bool cull_back_faces,
                       ScreenProjection& out) {
    const size_t vertices = tris.positions.size();
    out.clip_positions.resize(vertices);
    out.screen.resize(vertices);
    out.vertex_inside.resize(vertices);
    hikari::parallel_for(tbb::blocked_range<size_t>(0, vertices, 4096),
                         [&](const tbb::blocked_range<size_t>& range) {
                             for (size_t i = range.begin(); i != range.end(); ++i) {
                                 transform_vertex(view, tris.positions[i], out.clip_positions[i],
                                                  out.vertex_inside[i], out.screen[i]);
                             }
                         });

    const size_t n = tris.size();
    out.counts = {};
    out.counts.triangles_in = n;
    // The whole scene inside the clip volume and nothing to cull (a model in view): every
    // triangle is one screen triangle, its corners' screen vertices; no counting pass.
    const bool all_inside =
        !cull_back_faces && std::all_of(out.vertex_inside.begin(), out.vertex_inside.end(),
                                        [](uint8_t inside) { return inside != 0; });
    out.indexed = all_inside && out.indexed_allowed;
    if (out.indexed) {
        out.triangles.clear();
        return;
    }
    if (all_inside) {
        out.triangles.resize(n);
        hikari::parallel_for(
            tbb::blocked_range<size_t>(0, n, 4096), [&](const tbb::blocked_range<size_t>& range) {
                const IndexedScreenTriangles corners{out.screen.data(), tris.indices.data(), n};
                for (size_t t = range.begin(); t != range.end(); ++t) out.triangles[t] = corners[t];
            });
        return;
    }
    // Count the pieces of every triangle, place them by a prefix sum, then write them: the
    // output is in scene order whatever the thread count.
    out.offset.assign(n + 1, 0);
    out.fate.resize(n);
    hikari::parallel_for(
        tbb::blocked_range<size_t>(0, n, 4096), [&](const tbb::blocked_range<size_t>& range) {
            for (size_t t = range.begin(); t != range.end(); ++t)
                out.offset[t + 1] =
                    static_cast<uint32_t>(project_one(tris, view, out, static_cast<uint32_t>(t),
                                                      cull_back_faces, nullptr, out.fate[t]));
        });
    for (size_t t = 0; t < n; ++t) out.offset[t + 1] += out.offset[t];
    out.triangles.resize(out.offset[n]);
    hikari::parallel_for(
        tbb::blocked_range<size_t>(0, n, 4096), [&](const tbb::blocked_range<size_t>& range) {
            for (size_t t = range.begin(); t != range.end(); ++t) {
                uint8_t again = 0;
                if (out.offset[t + 1] > out.offset[t])
                    project_one(tris, view, out, static_cast<uint32_t>(t), cull_back_faces,
                                &out.triangles[out.offset[t]], again);
            }
        });
    for (const uint8_t f : out.fate) {
        out.counts.culled += f == k_culled;
        out.counts.clipped_away += f == k_clipped_away || f == k_not_finite;
        out.counts.cut += f == k_cut;
    }
}

ProjectedScene project_triangles(RasterScene scene, const RasterView& view, bool cull_back_faces) {
    ProjectedScene ps;
    ps.scene = std::move(scene);
    ps.view = view;
    ScreenProjection sp;
    project_to_screen(ps.scene.triangles, view, cull_back_faces, sp);
    ps.clip_positions = std::move(sp.clip_positions);
    ps.triangles = std::move(sp.triangles);
    ps.counts = sp.counts;
    return ps;
}

ProjectedScene project_scene(const Scene& scene, const RasterSettings& raster,
                             SphereGeometry spheres) {
    RasterScene rs = tessellate_scene(scene, spheres);
    const RasterView view = make_raster_view(scene.camera, rs, raster.sample_offset);
    return project_triangles(std::move(rs), view, raster.cull_back_faces);
}

}  // namespace hikari
