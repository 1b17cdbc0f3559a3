#pragma once
// Nearest-hit and shadow-ray queries against a whole scene: triangles through the wide (8-child,
// SIMD) BVH, spheres through a wide BVH of their own (sphere_bvh.h), asked second with the nearest
// triangle as its limit; infinite planes, which no box holds, tested directly. Built once per
// render, read by all threads.

#include "hikari/bvh/flat_intersector.h"
#include "hikari/bvh/sphere_bvh.h"
#include "hikari/bvh/surface_hit.h"
#include "hikari/bvh/triangle_hit.h"
#include "hikari/bvh/wide_bvh.h"
#include "hikari/bvh/wide_bvh_packet.h"
#include "hikari/core/build_cache.h"
#include "hikari/core/ray.h"
#include "hikari/frame/render_settings.h"
#include "hikari/geometry/surface_uv.h"
#include "hikari/scene/scene.h"

namespace hikari {

class SceneIntersector {
  public:
    /// Prepares acceleration structures for `scene`, which must outlive this object.
    explicit SceneIntersector(const Scene& scene);

    /// The nearest hit of `ray` inside `range`, if any (the lecture's 可視点, Alg 4.3).
    bool closest(const Ray& ray, Interval range, SurfaceHit& hit) const;
    /// Whether anything that casts shadows blocks `ray` inside `range` (shadow rays stop at the
    /// first blocker; objects with casts_shadow false are ignored).
    bool occluded(const Ray& ray, Interval range) const;

    /// Whether a shadow-casting triangle blocks `ray` inside `range` (occluded's first part).
    bool occluded_by_triangles(const Ray& ray, Interval range) const;
    /// Whether a shadow-casting sphere or plane blocks `ray` inside `range` (occluded's rest).
    bool occluded_by_spheres_and_planes(const Ray& ray, Interval range) const;
    /// Whether a shadow-casting sphere blocks `ray` inside `range`.
    bool occluded_by_spheres(const Ray& ray, Interval range) const;
    /// The nearest sphere hit by `ray` inside `range`, as testing every sphere in index order
    /// with intersect_sphere finds it (each later one strictly nearer): closest()'s sphere step.
    bool closest_sphere(const Ray& ray, Interval range, SphereHit& hit) const;
    /// occluded_by_triangles for the lanes `active` of a packet, each with its own interval:
    /// the mask of blocked lanes, each lane's answer exactly the single ray's (wide_bvh_packet.h).
    uint32_t occluded_by_triangles(const RayPacket& packet, uint32_t active) const;

    /// Fills `hit` for the nearest hit of `ray` found at distance `t` on primitive `index` of
    /// kind `kind` (Scene::spheres or Scene::planes; for triangles, `triangle` says which and
    /// where). What closest() does once it knows the nearest hit, for callers that searched
    /// another way (e.g. the bulk camera-ray front end, integrators/whitted/primary_hits.h).
    void describe_hit(const Ray& ray, float t, HitKind kind, size_t index,
                      const TriangleHit& triangle, SurfaceHit& hit) const;

    /// The texture coordinates of `hit` (geometry/surface_uv.h): a triangle's interpolated from
    /// its corners' (zero gradients and (0, 0) where the scene has none), a sphere's and a
    /// plane's from their mappings.
    SurfaceUv surface_uv(const SurfaceHit& hit) const;

    /// The vertex colour at `hit` (TriangleSet::colors): a triangle's interpolated from its
    /// corners', white for every other hit and where the scene has none.
    Vec3 surface_colour(const SurfaceHit& hit) const;

    /// The wide BVH over the scene's triangles.
    const WideBvh& bvh() const { return m_bvh; }
    /// The wide BVH shadow rays traverse: over the shadow-casting triangles (bvh() when all cast).
    const WideBvh& shadow_bvh() const { return m_all_cast ? m_bvh : m_shadow_bvh; }
    /// The scene's geometry as flat views, read now (what the kernels read; describe_hit too).
    FlatGeometry geometry() const { return FlatGeometry(m_scene); }
    /// The wide BVH over the scene's spheres.
    const SphereBvh& sphere_bvh() const { return m_spheres; }
    /// Wall time the BVH builds took, in milliseconds.
    double build_ms() const { return m_build_ms; }

  private:
    const Scene& m_scene;
    WideBvh m_bvh;
    WideBvh m_shadow_bvh;    ///< the shadow-casting triangles, when some do not cast
    bool m_all_cast = true;  ///< every triangle casts: shadow rays use m_bvh
    SphereBvh m_spheres;
    SphereBvh m_sphere_casters;      ///< the shadow-casting spheres, when some do not cast
    bool m_all_spheres_cast = true;  ///< every sphere casts: shadow rays use m_spheres
    double m_build_ms = 0;
};

/// The intersector of `scene`: kept in `cache` (built on the first render of a session, reused
/// until the geometry changes), or built for this render alone (no cache, or another scene
/// object). `built` says whether this call built it.
std::shared_ptr<const SceneIntersector> scene_intersector(const Scene& scene, BuildCache* cache,
                                                          bool* built = nullptr);

/// The BVH's figures of `intersector` for `--stats` (nothing when `stats` is null); `built`
/// false: it was kept from an earlier render (RenderStats::bvh_reused, no build time).
void report_bvh_stats(const SceneIntersector& intersector, RenderStats* stats, bool built = true);

}  // namespace hikari
