#pragma once
// A ray and the interval of distances along it that count.

#include <limits>

#include "hikari/core/vec.h"

namespace hikari {

inline constexpr float k_infinity = std::numeric_limits<float>::infinity();

/// A half-line origin + t * direction. Directions are unit length unless a caller says otherwise,
/// so that t is a distance.
struct Ray {
    Vec3 origin;
    Vec3 direction;

    constexpr Vec3 at(float t) const { return origin + direction * t; }
};

/// The open range of ray distances (t_min, t_max) in which a hit is accepted.
struct Interval {
    float min = 0.0f;
    float max = k_infinity;

    constexpr bool surrounds(float t) const { return min < t && t < max; }
};

}  // namespace hikari
