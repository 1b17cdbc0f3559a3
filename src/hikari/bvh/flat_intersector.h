#pragma once
// Nearest-hit and shadow-ray queries over flat arrays, one ray at a time, written once for the
// CPU and the GPU (HIKARI_HD): the scene's triangles through the same wide BVH the CPU's SIMD
// traversal walks (bvh/wide_bvh.h), tested with the same watertight triangle test
// (geometry/triangle_intersect.h); spheres and planes in index order with the lecture's
// ray-sphere and ray-plane tests (geometry/intersect.h). The answers are SceneIntersector's: the
// same nearest primitive and the same SurfaceHit (its describe_hit is describe_surface_hit).

#include <array>
#include <cmath>
#include <cstdint>

#include "hikari/bvh/surface_hit.h"
#include "hikari/bvh/triangle_hit.h"
#include "hikari/bvh/wide_bvh.h"
#include "hikari/core/flat_view.h"
#include "hikari/core/host_device.h"
#include "hikari/core/ray.h"
#include "hikari/geometry/intersect.h"
#include "hikari/geometry/surface_uv.h"
#include "hikari/geometry/triangle_intersect.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// A wide BVH's arrays as flat views.
struct FlatBvh {
    FlatView<WideBvhNode> nodes;
    FlatView<float> triangle_data;
    FlatView<uint32_t> triangle_ids;
    uint32_t root = WideBvhRef::k_empty;

    FlatBvh() = default;
    explicit FlatBvh(const WideBvh& bvh)
        : nodes(std::span<const WideBvhNode>(bvh.nodes.data(), bvh.nodes.size())),
          triangle_data(std::span<const float>(bvh.triangle_data.data(), bvh.triangle_data.size())),
          triangle_ids(std::span<const uint32_t>(bvh.triangle_ids.data(), bvh.triangle_ids.size())),
          root(bvh.root) {}
};

/// A scene's primitives as flat views (Scene's arrays, or their copies in GPU memory).
struct FlatGeometry {
    FlatView<Sphere> spheres;
    FlatView<Plane> planes;
    FlatView<Vec3> positions, normals;  ///< TriangleSet's
    FlatView<std::array<uint32_t, 3>> indices;
    FlatView<uint32_t> material;
    FlatView<PrimitiveId> id;
    FlatView<Vec2> uvs;     ///< per vertex; empty when no triangle has any
    FlatView<Vec3> colors;  ///< per vertex; empty when no object has any

    FlatGeometry() = default;
    explicit FlatGeometry(const Scene& scene)
        : spheres(scene.spheres),
          planes(scene.planes),
          positions(scene.triangles.positions),
          normals(scene.triangles.normals),
          indices(scene.triangles.indices),
          material(scene.triangles.material),
          id(scene.triangles.id),
          uvs(scene.triangles.uvs),
          colors(scene.triangles.colors) {}
};

/// Where the wide BVH's conservative slab test widens a box's exit distance (Ize 2013, "Robust
/// BVH Ray Traversal": 1 + 2 gamma(3)), so a box the exact ray touches is never culled.
inline constexpr float k_flat_exit_scale =
    1.0f + 2.0f * (3.0f * 0x1p-24f / (1.0f - 3.0f * 0x1p-24f));

/// Whether the ray (origin `o`, reciprocal direction `inv`, `negative` per axis where the
/// direction's sign bit is set) meets child `c` of `node` within [t_min, t_max].
/// `entry`, when set, receives where the ray enters it.
HIKARI_HD inline bool flat_child_hit(const WideBvhNode& node, uint32_t c, const float (&o)[3],
                                     const float (&inv)[3], const int (&negative)[3], float t_min,
                                     float t_max, float* entry = nullptr) {
    for (int a = 0; a < 3; ++a) {
        const float near = node.bounds[2 * a + negative[a]][c];
        const float far = node.bounds[2 * a + 1 - negative[a]][c];
        const float t_near = (near - o[a]) * inv[a];
        const float t_far = (far - o[a]) * inv[a] * k_flat_exit_scale;
        // NaN (a ray in a slab's plane, 0 · inf) constrains nothing: the comparisons are false.
        t_min = t_near > t_min ? t_near : t_min;
        t_max = t_far < t_max ? t_far : t_max;
    }
    if (entry) *entry = t_min;
    return t_min <= t_max;
}

/// The nearest triangle of `bvh` along `ray` inside `range` (k_any_hit false; `range.max`
/// shrinks to it and `hit` describes it), or whether any triangle lies there (k_any_hit true).
/// A depth-first walk with a fixed stack (k_wide_bvh_stack_size entries, the tree's guarantee);
/// the nearest hit visits a node's children nearest first, ties in slot order, and skips those
/// that start beyond the nearest hit so far, as the CPU's traversal (wide_bvh_kernel.h) does:
/// where two triangles tie, both walks then meet them in the same order.
template <bool k_any_hit>
HIKARI_HD bool traverse_flat_bvh(const FlatBvh& bvh, const Ray& ray, Interval& range,
                                 TriangleHit& hit) {
    if (bvh.root == WideBvhRef::k_empty) return false;
    const WatertightRay watertight(ray);
    float o[3], inv[3];
    int negative[3];
    for (int a = 0; a < 3; ++a) {
        o[a] = ray.origin[a];
        inv[a] = 1.0f / ray.direction[a];
        negative[a] = std::signbit(ray.direction[a]) ? 1 : 0;
    }
    uint32_t stack[k_wide_bvh_stack_size];
    float entries[k_any_hit ? 1 : k_wide_bvh_stack_size];  ///< where each pushed child starts
    uint32_t top = 0;
    entries[0] = range.min;
    stack[top++] = bvh.root;
    bool found = false;
    while (top > 0) {
        --top;
        if constexpr (!k_any_hit)
            if (entries[top] > range.max * k_flat_exit_scale) continue;
        const uint32_t ref = stack[top];
        if (WideBvhRef::is_leaf(ref)) {
            /* test the leaf's triangles */
            const uint32_t first = WideBvhRef::leaf_first(ref), count = WideBvhRef::leaf_count(ref);
            const float* block = &bvh.triangle_data[9 * size_t{first}];
            for (uint32_t i = 0; i < count; ++i) {
                Vec3 p0, p1, p2;
                load_leaf_triangle(block, count, i, p0, p1, p2);
                if constexpr (k_any_hit) {
                    if (triangle_occludes(watertight, p0, p1, p2, range)) return true;
                } else if (const auto h = intersect_triangle(watertight, p0, p1, p2, range)) {
                    range.max = h->t;
                    hit = {h->t, h->u, h->v, bvh.triangle_ids[first + i]};
                    found = true;
                }
            }
            continue;
        }
        /* push the children whose boxes the ray meets before the nearest hit so far */
        const WideBvhNode& node = bvh.nodes[ref];
        if constexpr (k_any_hit) {
            for (uint32_t c = 0; c < k_wide_bvh_width; ++c) {
                const uint32_t child = node.child[c];
                if (child == WideBvhRef::k_empty) continue;
                if (flat_child_hit(node, c, o, inv, negative, range.min, range.max))
                    stack[top++] = child;
            }
        } else {
            // Insertion sort by entry distance (ties keep slot order), pushed farthest first.
            uint32_t hit_refs[k_wide_bvh_width];
            float hit_entries[k_wide_bvh_width];
            uint32_t n = 0;
            for (uint32_t c = 0; c < k_wide_bvh_width; ++c) {
                const uint32_t child = node.child[c];
                float entry = 0.0f;
                if (child == WideBvhRef::k_empty ||
                    !flat_child_hit(node, c, o, inv, negative, range.min, range.max, &entry))
                    continue;
                uint32_t k = n++;
                for (; k > 0 && hit_entries[k - 1] > entry; --k) {
                    hit_refs[k] = hit_refs[k - 1];
                    hit_entries[k] = hit_entries[k - 1];
                }
                hit_refs[k] = child;
                hit_entries[k] = entry;
            }
            for (uint32_t k = n; k > 0; --k) {
                entries[top] = hit_entries[k - 1];
                stack[top++] = hit_refs[k - 1];
            }
        }
    }
    return found;
}

/// Fills `hit` for the nearest hit of `ray` at distance `t` on primitive `index` of kind `kind`
/// (for triangles, `triangle` says which and where): what every intersector does once it knows
/// the nearest hit.
HIKARI_HD inline void describe_surface_hit(const FlatGeometry& g, const Ray& ray, float t,
                                           HitKind kind, size_t index, const TriangleHit& triangle,
                                           SurfaceHit& hit) {
    hit.t = t;
    hit.position = ray.at(t);
    hit.kind = kind;
    const bool on_triangle = kind == HitKind::triangle;
    hit.index = on_triangle ? triangle.triangle : static_cast<uint32_t>(index);
    hit.bary_u = on_triangle ? triangle.u : 0.0f;
    hit.bary_v = on_triangle ? triangle.v : 0.0f;
    if (kind == HitKind::sphere) {
        const Sphere& s = g.spheres[index];
        hit.geometric_normal = (hit.position - s.center) / s.radius;
        hit.shading_normal = hit.geometric_normal;
        hit.material = s.material;
        hit.id = s.id;
        return;
    }
    if (kind == HitKind::plane) {
        const Plane& p = g.planes[index];
        hit.geometric_normal = p.normal;
        hit.shading_normal = hit.geometric_normal;
        hit.material = p.material;
        hit.id = p.id;
        return;
    }
    const std::array<uint32_t, 3>& corners = g.indices[triangle.triangle];
    const Vec3 p0 = g.positions[corners[0]], p1 = g.positions[corners[1]],
               p2 = g.positions[corners[2]];
    // The lecture's N = (P2 − P1) × (P3 − P2) (Fig 4.5).
    hit.geometric_normal = normalize(cross(p1 - p0, p2 - p1));
    const float w = 1.0f - triangle.u - triangle.v;
    // From the barycentrics rather than origin + t·direction: closer to the surface, which the
    // ray-offset of secondary rays relies on (Wächter & Binder 2019).
    hit.position = p0 * w + p1 * triangle.u + p2 * triangle.v;
    const Vec3 n = g.normals[corners[0]] * w + g.normals[corners[1]] * triangle.u +
                   g.normals[corners[2]] * triangle.v;
    const float len2 = dot(n, n);
    hit.shading_normal = len2 > 0.0f ? n / std::sqrt(len2) : hit.geometric_normal;
    hit.material = g.material[triangle.triangle];
    hit.id = g.id[triangle.triangle];
}

/// The texture coordinates of `hit` (geometry/surface_uv.h): a triangle's interpolated from its
/// corners' (zero gradients and (0, 0) where the scene has none), a sphere's and a plane's from
/// their mappings.
HIKARI_HD inline SurfaceUv surface_uv_of(const FlatGeometry& g, const SurfaceHit& hit) {
    if (hit.kind == HitKind::sphere) return sphere_uv(g.spheres[hit.index], hit.position);
    if (hit.kind == HitKind::plane) return plane_uv(g.planes[hit.index], hit.position);
    if (hit.kind != HitKind::triangle || g.uvs.empty()) return {};
    const std::array<uint32_t, 3>& c = g.indices[hit.index];
    const std::array<Vec2, 3> t{g.uvs[c[0]], g.uvs[c[1]], g.uvs[c[2]]};
    SurfaceUv out =
        triangle_uv_gradients({g.positions[c[0]], g.positions[c[1]], g.positions[c[2]]}, t);
    const float w = 1.0f - hit.bary_u - hit.bary_v;
    out.uv = {t[0].x * w + t[1].x * hit.bary_u + t[2].x * hit.bary_v,
              t[0].y * w + t[1].y * hit.bary_u + t[2].y * hit.bary_v};
    return out;
}

/// The vertex colour at `hit`: a triangle's interpolated from its corners', white for every
/// other hit and where the scene has none.
HIKARI_HD inline Vec3 surface_colour_of(const FlatGeometry& g, const SurfaceHit& hit) {
    if (hit.kind != HitKind::triangle || g.colors.empty()) return Vec3(1.0f);
    const std::array<uint32_t, 3>& c = g.indices[hit.index];
    const float w = 1.0f - hit.bary_u - hit.bary_v;
    return w * g.colors[c[0]] + hit.bary_u * g.colors[c[1]] + hit.bary_v * g.colors[c[2]];
}

/// The flat scene a kernel queries: its geometry, the BVH over every triangle and the one shadow
/// rays traverse (over the casters).
struct FlatIntersector {
    FlatGeometry geometry;
    FlatBvh triangles;         ///< every triangle
    FlatBvh shadow_triangles;  ///< the shadow-casting triangles

    /// The nearest hit of `ray` inside `range`, as SceneIntersector::closest finds it.
    HIKARI_HD bool closest(const Ray& ray, Interval range, SurfaceHit& hit) const {
        HitKind kind = HitKind::none;
        TriangleHit triangle_hit;
        if (traverse_flat_bvh<false>(triangles, ray, range, triangle_hit)) kind = HitKind::triangle;
        size_t index = 0;
        // Every sphere in index order, each later one strictly nearer (as the sphere BVH finds it).
        for (size_t i = 0; i < geometry.spheres.size(); ++i) {
            const Sphere& s = geometry.spheres[i];
            const float t = intersect_sphere(ray, s.center, s.radius, range);
            if (t == t) range.max = t, kind = HitKind::sphere, index = i;
        }
        for (size_t i = 0; i < geometry.planes.size(); ++i) {
            const Plane& p = geometry.planes[i];
            const float t = intersect_plane(ray, p.point, p.normal, range);
            if (t == t) range.max = t, kind = HitKind::plane, index = i;
        }
        if (kind == HitKind::none) return false;
        describe_surface_hit(geometry, ray, range.max, kind, index, triangle_hit, hit);
        return true;
    }

    /// Whether anything that casts shadows blocks `ray` inside `range`.
    HIKARI_HD bool occluded(const Ray& ray, Interval range) const {
        TriangleHit unused;
        if (traverse_flat_bvh<true>(shadow_triangles, ray, range, unused)) return true;
        for (size_t i = 0; i < geometry.spheres.size(); ++i) {
            const Sphere& s = geometry.spheres[i];
            if (s.casts_shadow && !std::isnan(intersect_sphere(ray, s.center, s.radius, range)))
                return true;
        }
        for (size_t i = 0; i < geometry.planes.size(); ++i) {
            const Plane& p = geometry.planes[i];
            if (p.casts_shadow && !std::isnan(intersect_plane(ray, p.point, p.normal, range)))
                return true;
        }
        return false;
    }
};

}  // namespace hikari
