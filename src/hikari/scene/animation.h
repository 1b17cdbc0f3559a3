#pragma once
// A scene's animation (docs/scene-format.md, "animation"): values given at key frames and
// interpolated between them, as POV-Ray's `clock` and Blender's key frames do. Positions take a
// straight line between keys (linear) or a Catmull-Rom spline through them (smooth; Catmull &
// Rom 1974, as a cubic Hermite curve with finite-difference tangents); rotations take the great
// arc between unit quaternions (slerp; Shoemake 1985, "Animating rotation with quaternion
// curves"). Everything is computed in double precision from the keys alone, so a frame's values
// do not depend on which frames were computed before it.

#include <cstddef>
#include <optional>
#include <vector>

#include "hikari/core/vec.h"

namespace hikari {

/// A point, direction or scale in double precision.
using Vec3d = Vec3T<double>;

/// How positions move between keys.
enum class KeyInterpolation {
    linear,  ///< straight lines between keys, constant speed in each interval
    smooth,  ///< a Catmull-Rom spline through the keys (no corner at a key)
};

/// One value at one frame.
template <class T>
struct Key {
    double frame = 0;
    T value{};
};

/// A value's keys in increasing frame order; empty: the value is not animated.
template <class T>
using Track = std::vector<Key<T>>;

/// A rotation as a unit quaternion w + x i + y j + z k.
struct Rotation {
    double w = 1, x = 0, y = 0, z = 0;
};

/// The rotation by `degrees` counter-clockwise about `axis` (not zero; normalized here), seen
/// from the axis' tip: what a scene's {"rotate": {"axis", "degrees"}} step does.
Rotation rotation_about(Vec3d axis, double degrees);

/// A rotation as a unit axis and an angle in degrees from 0 to 180; the identity is 0 degrees
/// about +y.
struct AxisAngle {
    Vec3d axis{0, 1, 0};
    double degrees = 0;
};
AxisAngle axis_angle(const Rotation& q);

/// `keys` at `frame`: the first key's value before it, the last's after it; in between, a
/// straight line (linear) or the Catmull-Rom spline of the keys (smooth). At a key, its value.
Vec3d sample(const Track<Vec3d>& keys, double frame, KeyInterpolation interpolation);
/// A number's keys at `frame`, always linear (a field of view or a scale stays within its keys).
double sample(const Track<double>& keys, double frame);
/// Rotation keys at `frame` by slerp along the shorter arc between neighbouring keys.
Rotation sample(const Track<Rotation>& keys, double frame);

/// The keys of a camera's values; an empty track leaves the scene's value.
struct CameraKeys {
    Track<Vec3d> eye, look_at, up;
    Track<double> fov_y;  ///< degrees
};

/// The keys of a transform applied after an object's own (or to a light): scale, then rotate
/// about the world's origin, then translate.
struct TransformKeys {
    Track<Vec3d> scale;  ///< per axis, linear
    Track<Rotation> rotate;
    Track<Vec3d> translate;
};

/// A transform's values at one frame; unset: that step is not animated.
struct TransformAtFrame {
    std::optional<Vec3d> scale;
    std::optional<AxisAngle> rotate;
    std::optional<Vec3d> translate;
};

/// `keys` at `frame`.
TransformAtFrame sample(const TransformKeys& keys, double frame, KeyInterpolation interpolation);

/// An object's or a light's transform keys.
struct TransformAnimation {
    size_t index = 0;  ///< into the scene file's "objects" or "lights"
    KeyInterpolation interpolation = KeyInterpolation::linear;
    TransformKeys keys;
};

/// A scene file's "animation" block.
struct Animation {
    int frame_count = 1;
    double fps = 24;
    KeyInterpolation camera_interpolation = KeyInterpolation::linear;
    CameraKeys camera;
    std::vector<TransformAnimation> objects, lights;
};

}  // namespace hikari
