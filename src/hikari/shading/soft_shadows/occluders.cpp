#include "hikari/shading/soft_shadows/occluders.h"

#include <algorithm>
#include <cmath>

#include "hikari/bvh/wide_bvh_builder.h"

namespace hikari {

namespace {

/// Whether the box [lo, hi] lies wholly outside one of `planes`.
bool box_outside(std::span<const Vec4> planes, Vec3 lo, Vec3 hi) {
    for (const Vec4& p : planes) {
        // The box corner farthest along the plane's normal.
        const Vec3 far{p.x >= 0.0f ? hi.x : lo.x, p.y >= 0.0f ? hi.y : lo.y,
                       p.z >= 0.0f ? hi.z : lo.z};
        if (p.x * far.x + p.y * far.y + p.z * far.z < p.w) return true;
    }
    return false;
}

bool triangle_outside(std::span<const Vec4> planes, Vec3 a, Vec3 b, Vec3 c) {
    for (const Vec4& p : planes) {
        const Vec3 n = p.xyz();
        if (dot(n, a) < p.w && dot(n, b) < p.w && dot(n, c) < p.w) return true;
    }
    return false;
}

/// Walks `tree`, visiting the children whose boxes `keep(lo, hi)` accepts and calling
/// `leaf(first, count)` for the slots of accepted leaves until it returns true.
template <class Keep, class Leaf>
bool walk(const WideBvh& tree, Keep&& keep, Leaf&& leaf) {
    if (tree.empty()) return false;
    uint32_t stack[k_wide_bvh_stack_size];
    int top = 0;
    stack[top++] = tree.root;
    while (top > 0) {
        const uint32_t ref = stack[--top];
        if (WideBvhRef::is_leaf(ref)) {
            if (leaf(WideBvhRef::leaf_first(ref), WideBvhRef::leaf_count(ref))) return true;
            continue;
        }
        const WideBvhNode& node = tree.nodes[ref];
        for (uint32_t i = 0; i < k_wide_bvh_width; ++i) {
            if (node.child[i] == WideBvhRef::k_empty) continue;
            const Vec3 lo{node.bounds[0][i], node.bounds[2][i], node.bounds[4][i]};
            const Vec3 hi{node.bounds[1][i], node.bounds[3][i], node.bounds[5][i]};
            if (keep(lo, hi)) stack[top++] = node.child[i];
        }
    }
    return false;
}

/// Calls `visit(p0, p1, p2)` for each triangle of the leaf at slots [first, first + count) of
/// `bvh` until it returns true.
template <class Visit>
bool each_leaf_triangle(const WideBvh& bvh, uint32_t first, uint32_t count, Visit&& visit) {
    const float* block = bvh.triangle_data.data() + 9 * static_cast<size_t>(first);
    for (uint32_t i = 0; i < count; ++i) {
        Vec3 a, b, c;
        load_leaf_triangle(block, count, i, a, b, c);
        if (visit(a, b, c)) return true;
    }
    return false;
}

/// Whether the ray from + t·dir, t in [0, t_max], meets the box [lo, hi] (slab test).
bool segment_meets_box(Vec3 from, Vec3 inv_dir, float t_max, Vec3 lo, Vec3 hi) {
    float t0 = 0.0f, t1 = t_max;
    for (int a = 0; a < 3; ++a) {
        float near = (lo[a] - from[a]) * inv_dir[a], far = (hi[a] - from[a]) * inv_dir[a];
        if (near > far) std::swap(near, far);
        t0 = std::max(t0, near);
        t1 = std::min(t1, far);
    }
    return t0 <= t1;
}

}  // namespace

OccluderSet::OccluderSet(std::span<const Vec3> positions,
                         std::span<const std::array<uint32_t, 3>> indices,
                         std::span<const uint8_t> casters, std::span<const Sphere> spheres,
                         std::span<const Plane> planes) {
    std::vector<std::array<uint32_t, 3>> casting;
    for (size_t t = 0; t < indices.size(); ++t)
        if (casters.empty() || casters[t]) casting.push_back(indices[t]);
    m_bvh = build_wide_bvh(positions, casting);
    for (const Sphere& s : spheres)
        if (s.casts_shadow) m_spheres.push_back(s);
    m_sphere_bvh = build_sphere_bvh(m_spheres);
    for (const Plane& p : planes)
        if (p.casts_shadow) m_planes.push_back(p);
}

void OccluderSet::for_each_triangle_in(std::span<const Vec4> planes,
                                       const std::function<void(Vec3, Vec3, Vec3)>& visit) const {
    walk(
        m_bvh, [&](Vec3 lo, Vec3 hi) { return !box_outside(planes, lo, hi); },
        [&](uint32_t first, uint32_t count) {
            return each_leaf_triangle(m_bvh, first, count, [&](Vec3 a, Vec3 b, Vec3 c) {
                if (!triangle_outside(planes, a, b, c)) visit(a, b, c);
                return false;
            });
        });
}

void OccluderSet::for_each_sphere_in(std::span<const Vec4> planes,
                                     const std::function<void(const Sphere&)>& visit) const {
    const WideBvh& tree = m_sphere_bvh.tree;
    walk(
        tree, [&](Vec3 lo, Vec3 hi) { return !box_outside(planes, lo, hi); },
        [&](uint32_t first, uint32_t count) {
            for (uint32_t i = first; i < first + count; ++i) visit(m_spheres[tree.triangle_ids[i]]);
            return false;
        });
}

bool OccluderSet::blocks_segment(Vec3 from, Vec3 dir, float t_max) const {
    const Vec3 inv{1.0f / dir.x, 1.0f / dir.y, 1.0f / dir.z};
    const auto meets_box = [&](Vec3 lo, Vec3 hi) {
        return segment_meets_box(from, inv, t_max, lo, hi);
    };
    const WideBvh& spheres = m_sphere_bvh.tree;
    const bool sphere_blocks = walk(spheres, meets_box, [&](uint32_t first, uint32_t count) {
        for (uint32_t i = first; i < first + count; ++i) {
            const Sphere& s = m_spheres[spheres.triangle_ids[i]];
            // A point on (or, tessellated, just inside) the sphere is lit or not by its horizon.
            const Vec3 oc = from - s.center;
            const float c = dot(oc, oc) - s.radius * s.radius * k_own_sphere;
            if (c <= 0.0f) continue;
            const float b = dot(oc, dir);
            const float disc = b * b - (dot(oc, oc) - s.radius * s.radius);
            if (b < 0.0f && disc > 0.0f && -b - std::sqrt(disc) < t_max) return true;
        }
        return false;
    });
    if (sphere_blocks) return true;
    return walk(m_bvh, meets_box, [&](uint32_t first, uint32_t count) {
        return each_leaf_triangle(m_bvh, first, count, [&](Vec3 a, Vec3 b, Vec3 c) {
            const Vec3 e1 = b - a, e2 = c - a;
            const Vec3 pv = cross(dir, e2);
            const float det = dot(e1, pv);
            if (det == 0.0f) return false;
            const float inv_det = 1.0f / det;
            const Vec3 tv = from - a;
            const float u = dot(tv, pv) * inv_det;
            if (u < 0.0f || u > 1.0f) return false;
            const Vec3 qv = cross(tv, e1);
            const float v = dot(dir, qv) * inv_det;
            if (v < 0.0f || u + v > 1.0f) return false;
            const float t = dot(e2, qv) * inv_det;
            return t > 0.0f && t < t_max;
        });
    });
}

}  // namespace hikari
