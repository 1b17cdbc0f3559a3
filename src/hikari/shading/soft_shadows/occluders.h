#pragma once
// The shadow casters an area light's analytic soft shadow looks for: triangles in a wide BVH
// (bvh/wide_bvh.h), found by the pyramid from a shaded point to the light (Nishita & Nakamae
// 1983 find them per point; the BVH keeps that from touching every triangle), the scene's
// spheres (in a BVH of their own, bvh/sphere_bvh.h), each occluding as the polygon of its outline
// seen from the point, and its infinite planes, which clip the light exactly.

#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "hikari/bvh/sphere_bvh.h"
#include "hikari/bvh/wide_bvh.h"
#include "hikari/core/build_cache.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// A point within √k_own_sphere radii of a sphere's centre lies on the sphere (or on its
/// tessellation, whose facets dip up to 1 − cos(π/16) ≈ 2% inside): the sphere does not shadow
/// it beyond its own horizon.
inline constexpr float k_own_sphere = 1.0f + 1e-3f;

/// Triangles, spheres and planes that cast shadows, read by all threads.
class OccluderSet {
  public:
    /// The triangles `indices` of `positions` that `casters` marks (all when it is empty), and
    /// the shadow-casting spheres and planes of `spheres` and `planes`.
    OccluderSet(std::span<const Vec3> positions, std::span<const std::array<uint32_t, 3>> indices,
                std::span<const uint8_t> casters, std::span<const Sphere> spheres,
                std::span<const Plane> planes);
    /// The shadow casters of `scene`.
    explicit OccluderSet(const Scene& scene)
        : OccluderSet(scene.triangles.positions, scene.triangles.indices,
                      scene.triangles.casts_shadow, scene.spheres, scene.planes) {}

    /// Calls `visit(p0, p1, p2)` for every triangle that may meet the convex region bounded by
    /// `planes` (each plane (n, d) keeps the points x with dot(n, x) >= d): every triangle that
    /// does, and some near it.
    void for_each_triangle_in(std::span<const Vec4> planes,
                              const std::function<void(Vec3, Vec3, Vec3)>& visit) const;
    /// Whether a triangle blocks the segment from `from` to from + t·dir for t in (0, t_max)
    /// (Möller & Trumbore 1997); planes are not asked.
    bool blocks_segment(Vec3 from, Vec3 dir, float t_max) const;

    /// Calls `visit(sphere)` for every casting sphere that may meet the region bounded by
    /// `planes` (those of the spheres' BVH leaves whose boxes are not wholly outside it).
    void for_each_sphere_in(std::span<const Vec4> planes,
                            const std::function<void(const Sphere&)>& visit) const;

    std::span<const Plane> planes() const { return m_planes; }
    size_t triangle_count() const { return m_bvh.triangle_count(); }

  private:
    WideBvh m_bvh;
    std::vector<Sphere> m_spheres;  ///< the casting spheres
    SphereBvh m_sphere_bvh;         ///< over m_spheres
    std::vector<Plane> m_planes;
};

/// The shadow casters of `scene`: kept in `cache` until the geometry changes, or built for this
/// render alone (no cache, or another scene object).
inline std::shared_ptr<const OccluderSet> shadow_occluders(const Scene& scene, BuildCache* cache) {
    return cached_or_built<OccluderSet>(cache, &scene, "shadow occluders", SceneParts::geometry,
                                        [&] { return OccluderSet(scene); });
}

}  // namespace hikari
