#pragma once
// The scene as plain data: loaders build it, methods only read it (ARCHITECTURE.md, data flow).

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "hikari/scene/camera.h"
#include "hikari/scene/light.h"
#include "hikari/scene/material.h"

namespace hikari {

/// Primitive ids number what the scene file lists, in order: a sphere, plane or triangle object
/// is one primitive, a mesh contributes its triangles one after another in file order.
using PrimitiveId = uint32_t;

/// The range of Sphere::segments.
inline constexpr int k_min_sphere_segments = 3, k_max_sphere_segments = 4096;

/// A sphere (ray–sphere: the lecture's A t² + B t + C = 0).
struct Sphere {
    Vec3 center;
    float radius = 1;
    uint32_t material = 0;  ///< index into Scene::materials
    PrimitiveId id = 0;
    bool casts_shadow = true;  ///< false: shadow rays pass through it
    /// Polygons around the equator when a raster method tessellates the sphere (half as many
    /// bands from pole to pole); 0: enough for the sphere's size in the image (raster/
    /// tessellate.h). The ray tracer meets the exact sphere either way.
    uint32_t segments = 0;
};

/// An infinite, two-sided plane through `point` with unit `normal`.
struct Plane {
    Vec3 point;
    Vec3 normal{0, 1, 0};
    uint32_t material = 0;
    PrimitiveId id = 0;
    bool casts_shadow = true;  ///< false: shadow rays pass through it
    /// World units per texture repeat of the planar mapping (geometry/surface_uv.h, plane_uv).
    float uv_scale = 1.0f;
};

/// Every triangle of the scene in one flat indexed array, world space.
struct TriangleSet {
    std::vector<Vec3> positions;  ///< world-space vertex positions
    std::vector<Vec3> normals;    ///< unit shading normal per vertex
    /// Texture coordinates per vertex, (0, 0) the image's lower-left corner (the OBJ and OpenGL
    /// convention); empty when no triangle has any.
    std::vector<Vec2> uvs;
    /// Linear RGB per vertex (a PLY scan's colours), white for vertices of objects without;
    /// empty when no object has any. Read where the triangle's material has vertex_colours.
    std::vector<Vec3> colors;
    std::vector<std::array<uint32_t, 3>> indices;  ///< vertex indices per triangle,
                                                   ///< counter-clockwise seen from the front
    std::vector<uint32_t> material;                ///< material index per triangle
    std::vector<PrimitiveId> id;                   ///< primitive id per triangle
    /// Per triangle, 0 where shadow rays pass through it; empty means every triangle casts.
    std::vector<uint8_t> casts_shadow;
    /// Per triangle, bit k set where the edge from corner k to corner (k + 1) % 3 is an edge of
    /// the model's own face (a fan-triangulated polygon's diagonals are not); empty means every
    /// edge of every triangle is. Line drawings (wireframe, hidden lines) draw only these.
    std::vector<uint8_t> edge_flags;

    size_t size() const { return indices.size(); }
};

/// TriangleSet::edge_flags of a triangle whose three edges are all the model's.
inline constexpr uint8_t k_all_edges = 7;

/// The edge flags of triangle (a, c, b) given those of (a, b, c): swapping the last two corners
/// turns edge 0 (a → b) into edge 2 and edge 2 (c → a) into edge 0; edge 1 stays.
constexpr uint8_t mirrored_edge_flags(uint8_t flags) {
    return static_cast<uint8_t>((flags & 2) | ((flags & 1) << 2) | ((flags & 4) >> 2));
}

/// What rays that hit nothing see, by direction (ray tracing; raster methods use the
/// background colour).
struct Sky {
    bool gradient = false;  ///< false: the scene's background colour
    Vec3 horizon{0.0f};     ///< colour for directions with y <= 0
    Vec3 zenith{0.0f};      ///< colour straight up; linear in between (POV-Ray's `gradient y`)

    /// The colour seen along unit direction `dir` (each lane's, for a pack), or `background`
    /// without a gradient.
    template <class F>
    HIKARI_INLINE HIKARI_HD Vec3T<F> colour_toward(const Vec3T<F>& dir, Vec3 background) const {
        if (!gradient) return Vec3T<F>(background);
        const F t = select(dir.y < F(0.0f), F(0.0f), select(dir.y > F(1.0f), F(1.0f), dir.y));
        return Vec3T<F>(horizon) * (F(1.0f) - t) + Vec3T<F>(zenith) * t;
    }
    HIKARI_HD Vec3 colour(Vec3 dir, Vec3 background) const {
        return colour_toward<float>(dir, background);
    }
};

/// Depth cueing, the lecture's Fig 4.1b (近：明るい、はっきり / 遠：暗い、ぼやけ): the colour of a
/// point at eye distance d is blended toward `color` as w·colour + (1 − w)·color with
/// w = clamp((far − d) / (far − near), 0, 1), after a blur whose radius grows from 0 at `near`
/// to `blur` pixels at `far` (frame/depth_cue.h).
struct DepthCue {
    float near = 0.0f;          ///< eye distance where the blend starts (w = 1 nearer)
    float far = 1.0f;           ///< eye distance where only the cue colour is left (> near)
    std::optional<Vec3> color;  ///< linear RGB; the scene's background when unset
    float blur = 0.0f;          ///< blur radius at `far` in pixels (0: no blur)
};

/// A whole scene: camera, lights, materials and geometry.
struct Scene {
    Camera camera;
    Vec3 background{0.0f};  ///< colour of rays that hit nothing
    Vec3 ambient{0.0f};     ///< ambient light intensity Ia
    Sky sky;                ///< colour of escaping rays in ray tracing
    /// false: rays and pixels that meet no surface see black instead of the background, sky,
    /// environment or an area light's face (shading/shading_terms.h: one term alone).
    bool show_background = true;
    std::optional<DepthCue> depth_cue;  ///< every method's colour blended by distance, when set
    std::vector<Material> materials;
    std::vector<Light> lights;
    std::vector<Sphere> spheres;
    std::vector<Plane> planes;
    TriangleSet triangles;
    uint32_t primitive_count = 0;  ///< number of primitive ids handed out
};

}  // namespace hikari
