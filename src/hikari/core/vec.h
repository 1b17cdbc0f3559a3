#pragma once
// Small fixed-size vectors: the points, directions, normals and RGB colours of every stage.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "hikari/core/lanes.h"

namespace hikari {

/// A 2-vector of floats (texture coordinates, raster positions).
struct Vec2 {
    float x = 0, y = 0;
};

/// A 3-vector: a point, a direction, a normal or a linear RGB colour. `F` is the number type:
/// float for one point (`Vec3`), or a pack of SIMD lanes (core/lanes.h) for many points at once,
/// so that shading code written once over `F` serves both (as Mitsuba 3 templates on `Float`).
template <class F>
struct Vec3T {
    F x = F(), y = F(), z = F();  ///< zero for float; packs stay unset until assigned

    constexpr Vec3T() = default;
    HIKARI_INLINE HIKARI_HD constexpr Vec3T(F x_, F y_, F z_) : x(x_), y(y_), z(z_) {}
    /// A vector with all three components equal to `s`.
    HIKARI_INLINE HIKARI_HD constexpr explicit Vec3T(F s) : x(s), y(s), z(s) {}
    /// Every lane of a pack holding the float vector `v` (or a copy, for F = float).
    template <class G>
    requires(!std::is_same_v<G, F>) HIKARI_INLINE HIKARI_HD
        constexpr explicit Vec3T(const Vec3T<G>& v)
        : x(F(v.x)), y(F(v.y)), z(F(v.z)) {}

    HIKARI_INLINE HIKARI_HD constexpr F operator[](int i) const {
        return i == 0 ? x : (i == 1 ? y : z);
    }
    HIKARI_INLINE HIKARI_HD constexpr F& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
    HIKARI_INLINE HIKARI_HD constexpr Vec3T& operator+=(const Vec3T& b) {
        return *this = {x + b.x, y + b.y, z + b.z};
    }
    HIKARI_INLINE HIKARI_HD constexpr Vec3T& operator-=(const Vec3T& b) {
        return *this = {x - b.x, y - b.y, z - b.z};
    }
    HIKARI_INLINE HIKARI_HD constexpr Vec3T& operator*=(F s) {
        return *this = {x * s, y * s, z * s};
    }
    bool operator==(const Vec3T&) const = default;  // deleted for packs (no bool result)
};

/// One point, direction, normal or colour.
using Vec3 = Vec3T<float>;

/// The scalar argument of a vector operation: not deduced, so `v * 2` and `0.5f * v` convert.
template <class F>
using ScalarOf = std::type_identity_t<F>;

template <class F>
HIKARI_INLINE HIKARI_HD constexpr Vec3T<F> operator+(const Vec3T<F>& a, const Vec3T<F>& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class F>
HIKARI_INLINE HIKARI_HD constexpr Vec3T<F> operator-(const Vec3T<F>& a, const Vec3T<F>& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class F>
HIKARI_INLINE HIKARI_HD constexpr Vec3T<F> operator-(const Vec3T<F>& a) {
    return {-a.x, -a.y, -a.z};
}
/// Component-wise product (colour times colour, or scaling per axis).
template <class F>
HIKARI_INLINE HIKARI_HD constexpr Vec3T<F> operator*(const Vec3T<F>& a, const Vec3T<F>& b) {
    return {a.x * b.x, a.y * b.y, a.z * b.z};
}
template <class F>
HIKARI_INLINE HIKARI_HD constexpr Vec3T<F> operator*(const Vec3T<F>& a, ScalarOf<F> s) {
    return {a.x * s, a.y * s, a.z * s};
}
template <class F>
HIKARI_INLINE HIKARI_HD constexpr Vec3T<F> operator*(ScalarOf<F> s, const Vec3T<F>& a) {
    return a * s;
}
template <class F>
HIKARI_INLINE HIKARI_HD constexpr Vec3T<F> operator/(const Vec3T<F>& a, ScalarOf<F> s) {
    return a * (F(1.0f) / s);
}
template <class F>
HIKARI_INLINE HIKARI_HD constexpr Vec3T<F> operator/(const Vec3T<F>& a, const Vec3T<F>& b) {
    return {a.x / b.x, a.y / b.y, a.z / b.z};
}
template <class F>
HIKARI_INLINE HIKARI_HD constexpr F dot(const Vec3T<F>& a, const Vec3T<F>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
constexpr Vec3 cross(Vec3 a, Vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
HIKARI_HD inline float length(Vec3 a) { return std::sqrt(dot(a, a)); }
/// `a` scaled to unit length; the caller guarantees `a` is not zero.
HIKARI_HD inline Vec3 normalize(Vec3 a) { return a / length(a); }

constexpr Vec3 min(Vec3 a, Vec3 b) {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
constexpr Vec3 max(Vec3 a, Vec3 b) {
    return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
constexpr float max_component(Vec3 a) { return std::max(a.x, std::max(a.y, a.z)); }
constexpr float min_component(Vec3 a) { return std::min(a.x, std::min(a.y, a.z)); }
constexpr Vec3 lerp(Vec3 a, Vec3 b, float t) { return a * (1.0f - t) + b * t; }

HIKARI_HD inline bool is_finite(Vec3 a) {
    return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

/// `a` where `m`, else `b`, per component (and per lane, for packs).
template <class M, class F>
HIKARI_INLINE HIKARI_HD Vec3T<F> select(const M& m, const Vec3T<F>& a, const Vec3T<F>& b) {
    return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z)};
}

/// Mirror direction of `incident` (pointing toward the surface) about unit normal `n`:
/// the lecture's R = L + 2aN with a = -L·N.
template <class F>
HIKARI_INLINE HIKARI_HD constexpr Vec3T<F> reflect(const Vec3T<F>& incident, const Vec3T<F>& n) {
    return incident + F(2.0f) * (-dot(incident, n)) * n;
}

/// A 4-vector of floats: a point or direction in homogeneous coordinates.
struct Vec4 {
    float x = 0, y = 0, z = 0, w = 0;

    constexpr Vec4() = default;
    constexpr Vec4(float x_, float y_, float z_, float w_) : x(x_), y(y_), z(z_), w(w_) {}
    constexpr Vec4(Vec3 v, float w_) : x(v.x), y(v.y), z(v.z), w(w_) {}
    constexpr Vec3 xyz() const { return {x, y, z}; }
    constexpr bool operator==(const Vec4&) const = default;
};

constexpr Vec4 operator+(Vec4 a, Vec4 b) { return {a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w}; }
constexpr Vec4 operator-(Vec4 a, Vec4 b) { return {a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w}; }
constexpr Vec4 operator*(Vec4 a, float s) { return {a.x * s, a.y * s, a.z * s, a.w * s}; }
constexpr float dot(Vec4 a, Vec4 b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }

}  // namespace hikari
