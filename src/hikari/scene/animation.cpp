#include "hikari/scene/animation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hikari {

namespace {

constexpr double k_degrees_per_radian = 180.0 / std::numbers::pi;

/// The interval of `keys` (at least two) that `frame` lies in, strictly between its first and
/// last key: the index of its left key and where `frame` is across it, 0 to 1.
template <class T>
std::pair<size_t, double> interval_at(const Track<T>& keys, double frame) {
    const auto right = std::upper_bound(keys.begin(), keys.end(), frame,
                                        [](double f, const Key<T>& k) { return f < k.frame; });
    const auto i = static_cast<size_t>(right - keys.begin()) - 1;
    return {i, (frame - keys[i].frame) / (keys[i + 1].frame - keys[i].frame)};
}

/// The value at a key, or the held end value outside the keys; nullopt strictly inside.
template <class T>
std::optional<T> at_key_or_end(const Track<T>& keys, double frame) {
    if (frame <= keys.front().frame) return keys.front().value;
    if (frame >= keys.back().frame) return keys.back().value;
    for (const Key<T>& k : keys)
        if (k.frame == frame) return k.value;
    return std::nullopt;
}

/// Catmull-Rom's tangent at key j, per frame: the slope from the key before it to the key after
/// it (one-sided at the ends, so two keys alone give a straight line).
Vec3d tangent(const Track<Vec3d>& keys, size_t j) {
    const size_t before = j == 0 ? 0 : j - 1;
    const size_t after = std::min(j + 1, keys.size() - 1);
    return (keys[after].value - keys[before].value) / (keys[after].frame - keys[before].frame);
}

}  // namespace

Rotation rotation_about(Vec3d axis, double degrees) {
    const double half = 0.5 * degrees / k_degrees_per_radian;
    const Vec3d a = axis / std::sqrt(dot(axis, axis));
    const double s = std::sin(half);
    return {std::cos(half), a.x * s, a.y * s, a.z * s};
}

AxisAngle axis_angle(const Rotation& q) {
    // q and −q are the same rotation: take the one with w ≥ 0, whose angle is at most 180°.
    const double sign = q.w < 0 ? -1.0 : 1.0;
    const Vec3d v{q.x * sign, q.y * sign, q.z * sign};
    const double s = std::sqrt(dot(v, v));
    if (!(s > 1e-12)) return {};
    return {v / s, 2.0 * std::atan2(s, q.w * sign) * k_degrees_per_radian};
}

Vec3d sample(const Track<Vec3d>& keys, double frame, KeyInterpolation interpolation) {
    if (const std::optional<Vec3d> held = at_key_or_end(keys, frame)) return *held;
    const auto [i, u] = interval_at(keys, frame);
    const Vec3d& p0 = keys[i].value;
    const Vec3d& p1 = keys[i + 1].value;
    if (interpolation == KeyInterpolation::linear) return p0 + (p1 - p0) * u;
    // A cubic Hermite curve through p0 and p1 with Catmull-Rom's tangents, scaled from per
    // frame to per interval.
    const double h = keys[i + 1].frame - keys[i].frame;
    const double u2 = u * u, u3 = u2 * u;
    return p0 * (2 * u3 - 3 * u2 + 1) + tangent(keys, i) * (h * (u3 - 2 * u2 + u)) +
           p1 * (-2 * u3 + 3 * u2) + tangent(keys, i + 1) * (h * (u3 - u2));
}

double sample(const Track<double>& keys, double frame) {
    if (const std::optional<double> held = at_key_or_end(keys, frame)) return *held;
    const auto [i, u] = interval_at(keys, frame);
    return keys[i].value + (keys[i + 1].value - keys[i].value) * u;
}

Rotation sample(const Track<Rotation>& keys, double frame) {
    if (const std::optional<Rotation> held = at_key_or_end(keys, frame)) return *held;
    const auto [i, u] = interval_at(keys, frame);
    const Rotation& a = keys[i].value;
    Rotation b = keys[i + 1].value;
    double cosine = a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
    if (cosine < 0) {  // −b is the same rotation, on the shorter arc from a
        b = {-b.w, -b.x, -b.y, -b.z};
        cosine = -cosine;
    }
    // Shoemake's slerp: sin((1−u)θ)/sin θ · a + sin(uθ)/sin θ · b; nearly equal keys blend
    // linearly, where sin θ would divide by almost nothing.
    double wa = 1 - u, wb = u;
    if (cosine < 0.9999) {
        const double theta = std::acos(cosine);
        wa = std::sin((1 - u) * theta) / std::sin(theta);
        wb = std::sin(u * theta) / std::sin(theta);
    }
    Rotation q{wa * a.w + wb * b.w, wa * a.x + wb * b.x, wa * a.y + wb * b.y, wa * a.z + wb * b.z};
    const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    return {q.w / n, q.x / n, q.y / n, q.z / n};
}

TransformAtFrame sample(const TransformKeys& keys, double frame, KeyInterpolation interpolation) {
    TransformAtFrame t;
    if (!keys.scale.empty()) t.scale = sample(keys.scale, frame, KeyInterpolation::linear);
    if (!keys.rotate.empty()) t.rotate = axis_angle(sample(keys.rotate, frame));
    if (!keys.translate.empty()) t.translate = sample(keys.translate, frame, interpolation);
    return t;
}

}  // namespace hikari
