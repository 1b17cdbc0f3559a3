#pragma once
// The vertex stage of the lecture's pipeline (Fig 4.2): p_s = V P M p_w, then back-face culling
// (Fig 4.3), clipping in homogeneous clip space and the perspective divide. Its output, a list of
// ScreenTriangles, is what every hidden-surface method (zbuffer, scanline, depth sort) consumes.

#include <vector>

#include "hikari/core/mat4.h"
#include "hikari/raster/cull.h"
#include "hikari/raster/raster_scene.h"
#include "hikari/raster/raster_settings.h"
#include "hikari/raster/screen_triangle.h"
#include "hikari/raster/tessellate.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// The camera as a chain of matrices, with near and far planes fitted to the scene.
struct RasterView {
    Vec3 eye;
    Vec3 forward;          ///< the unit view direction of an orthographic camera (culling's V)
    float near_plane = 0;  ///< view-space distance of the near clipping plane, > 0
    float far_plane = 0;   ///< beyond every vertex: nothing is clipped at the far plane
    int width = 0, height = 0;
    Mat4 view_from_world;   ///< look_at of the camera
    Mat4 clip_from_view;    ///< perspective(fov, aspect, near, far)
    Mat4 screen_from_clip;  ///< viewport(width, height), applied after the divide by w
    Mat4 clip_from_world;   ///< clip_from_view * view_from_world
    /// clip_from_view is a parallel projection (core/mat4.h orthographic, w = 1), as a shadow
    /// map of a directional light is: ScreenVertex::inv_w then holds 1.5 − 0.5 z_ndc instead of
    /// 1 / w, which is affine across a triangle as 1 / w is under perspective and larger for
    /// nearer points, so every depth test works unchanged.
    bool orthographic = false;
    /// Where pixels are sampled, relative to their centres (RasterSettings::sample_offset): the
    /// exact spheres' camera rays go through centre + offset.
    Vec2 sample_offset{0.0f, 0.0f};

    /// The lecture's view vector V toward world point `p` (Fig 4.5, D = V·N): from the eye, or
    /// the view direction itself under a parallel projection.
    Vec3 view_vector(Vec3 p) const { return orthographic ? forward : p - eye; }

    /// The depth key ScreenVertex::position.z of world point `p`, whose 1 / w is `inv_w`:
    /// −near / w, or under a parallel projection −near (1.5 − 0.5 z_ndc).
    float depth_key(Vec3 p, float inv_w) const {
        if (!orthographic) return -near_plane * inv_w;
        return -near_plane * (1.5f - 0.5f * (clip_from_world * Vec4(p, 1.0f)).z);
    }
};

/// Whether `view` sees the back of triangle t of `tris` (raster/cull.h, D = V·N > 0 with the
/// view's V).
inline bool is_back_facing(const RasterView& view, const TriangleSet& tris, size_t t) {
    const auto& idx = tris.indices[t];
    const Vec3 p1 = tris.positions[idx[0]];
    return is_back_face_along(p1, tris.positions[idx[1]], tris.positions[idx[2]],
                              view.view_vector(p1));
}

/// Fits the view to `scene`'s bounds: far just beyond the farthest vertex; near at 0.9 times the
/// smallest view depth the bounding box can have inside the frustum, but at least 10⁻⁶ far. Depth
/// tests should compare view depth 1 / inv_w, whose float precision is relative, rather than
/// ScreenVertex::position.z, which degrades with far / near.
RasterView make_raster_view(const Camera& camera, const RasterScene& scene,
                            Vec2 sample_offset = {0.0f, 0.0f});

/// What the vertex stage did with the scene's triangles (`--stats`).
struct VertexStageCounts {
    size_t triangles_in = 0;  ///< tessellated scene triangles
    size_t culled = 0;        ///< dropped as back faces (D = V·N > 0)
    size_t clipped_away = 0;  ///< wholly outside the near plane or guard band (or not finite)
    size_t cut = 0;           ///< crossing a clip plane: kept in pieces
};

/// A scene after the vertex stage.
struct ProjectedScene {
    RasterScene scene;                      ///< the world-space triangles (attributes for shading)
    RasterView view;                        ///< the transforms used
    std::vector<Vec4> clip_positions;       ///< clip_from_world · p for every vertex of `scene`
    std::vector<ScreenTriangle> triangles;  ///< in scene order; a clipped source triangle's
                                            ///< pieces follow one another
    VertexStageCounts counts;
};

/// The vertex stage's output for one frame, with its scratch: projecting frame after frame into
/// the same ScreenProjection allocates nothing once it has grown to size.
struct ScreenProjection {
    std::vector<Vec4> clip_positions;       ///< clip_from_world · p for every vertex
    std::vector<ScreenTriangle> triangles;  ///< in triangle order; pieces of a clipped one follow
    /// Input: a caller that can draw IndexedScreenTriangles (raster/zbuffer.h) allows
    /// project_to_screen to leave `triangles` empty when every triangle is one screen triangle.
    bool indexed_allowed = false;
    /// Output: `triangles` is empty; screen triangle t is triangle t's corners in `screen`.
    bool indexed = false;
    VertexStageCounts counts;
    std::vector<ScreenVertex> screen;    ///< every vertex inside the clip volume, projected
    std::vector<uint8_t> vertex_inside;  ///< 1 where the vertex is inside the clip volume
    std::vector<uint32_t> offset;        ///< first screen triangle of each triangle
    std::vector<uint8_t> fate;           ///< what the stage did with each triangle
};

/// The vertex stage of `tris` through `view` into `out`: culls back faces when
/// `cull_back_faces`, clips in clip space, divides by w and maps to pixels; parallel, and the
/// output does not depend on the thread count.
void project_to_screen(const TriangleSet& tris, const RasterView& view, bool cull_back_faces,
                       ScreenProjection& out);

/// Projects every triangle of `scene` through `view`: culls back faces when `cull_back_faces`
/// (D = V·N > 0, raster/cull.h), clips in clip space (raster/clip.h), divides by w and maps to
/// pixels. Runs in parallel over triangles; the output order does not depend on the threads.
ProjectedScene project_triangles(RasterScene scene, const RasterView& view, bool cull_back_faces);

/// tessellate_scene, make_raster_view and project_triangles with `raster.cull_back_faces`.
/// Exact spheres (`spheres`) stay in ProjectedScene::scene.spheres, unprojected.
ProjectedScene project_scene(const Scene& scene, const RasterSettings& raster,
                             SphereGeometry spheres = SphereGeometry::tessellated);

}  // namespace hikari
