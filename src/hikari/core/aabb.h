#pragma once
// Axis-aligned bounding boxes: the bounding volumes of the BVH and of whole meshes.

#include "hikari/core/ray.h"
#include "hikari/core/vec.h"

namespace hikari {

/// A closed axis-aligned box [min, max]. The default box is empty (min = +inf, max = -inf), so
/// extending it by anything yields that thing.
struct Aabb {
    Vec3 min{k_infinity};
    Vec3 max{-k_infinity};

    /// The smallest box holding one point.
    static constexpr Aabb from_point(Vec3 p) { return {p, p}; }

    /// Grows the box to hold `p`.
    constexpr void extend(Vec3 p) {
        min = hikari::min(min, p);
        max = hikari::max(max, p);
    }
    /// Grows the box to hold `b`.
    constexpr void extend(const Aabb& b) {
        min = hikari::min(min, b.min);
        max = hikari::max(max, b.max);
    }
    /// True when the box holds no point (some max < min).
    constexpr bool empty() const { return max.x < min.x || max.y < min.y || max.z < min.z; }
    /// max - min; negative components for an empty box.
    constexpr Vec3 extent() const { return max - min; }
    /// The distance from `p` to the nearest point of the box (0 inside).
    float distance_to(Vec3 p) const {
        return length(hikari::max(hikari::max(min - p, p - max), Vec3(0.0f)));
    }
    /// The centre point; meaningless for an empty box.
    constexpr Vec3 center() const { return (min + max) * 0.5f; }
    /// Half the surface area (the SAH only needs ratios of areas); 0 for an empty box.
    constexpr float half_area() const {
        if (empty()) return 0.0f;
        const Vec3 e = extent();
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }
    /// The axis (0 = x, 1 = y, 2 = z) along which the box is longest.
    constexpr int largest_axis() const {
        const Vec3 e = extent();
        return e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
    }
    /// True when `b` lies inside this box (boundaries included).
    constexpr bool contains(const Aabb& b) const {
        return min.x <= b.min.x && min.y <= b.min.y && min.z <= b.min.z && b.max.x <= max.x &&
               b.max.y <= max.y && b.max.z <= max.z;
    }
    constexpr bool operator==(const Aabb&) const = default;
};

/// The smallest box holding both `a` and `b`.
constexpr Aabb merge(Aabb a, const Aabb& b) {
    a.extend(b);
    return a;
}

}  // namespace hikari
