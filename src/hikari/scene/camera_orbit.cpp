#include "hikari/scene/camera_orbit.h"

#include <array>
#include <cmath>
#include <numbers>

namespace hikari {

namespace {

using Vec3d = std::array<double, 3>;

Vec3d to_double(Vec3 v) { return {v.x, v.y, v.z}; }

double dot(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Vec3d cross(const Vec3d& a, const Vec3d& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace

Camera orbited_camera(const Camera& camera, double turns) {
    Vec3d axis = to_double(camera.up);
    const double axis_length = std::sqrt(dot(axis, axis));
    if (!(axis_length > 0.0)) return camera;  // no up vector: no axis to turn about
    for (double& a : axis) a /= axis_length;
    const Vec3d centre = to_double(camera.look_at);
    const Vec3d eye = to_double(camera.eye);
    const Vec3d offset{eye[0] - centre[0], eye[1] - centre[1], eye[2] - centre[2]};
    // Rodrigues' rotation formula: v cos θ + (k × v) sin θ + k (k · v)(1 − cos θ).
    const double angle = 2.0 * std::numbers::pi * turns;
    const double c = std::cos(angle), s = std::sin(angle), along = dot(axis, offset);
    const Vec3d k_cross_v = cross(axis, offset);
    Camera turned = camera;
    for (int i = 0; i < 3; ++i) {
        const double v = offset[i] * c + k_cross_v[i] * s + axis[i] * along * (1.0 - c);
        turned.eye[i] = static_cast<float>(centre[i] + v);
    }
    return turned;
}

Camera turntable_camera(const Camera& camera, int frame, int frame_count) {
    if (frame == 0 || frame_count <= 0) return camera;
    return orbited_camera(camera, static_cast<double>(frame) / frame_count);
}

}  // namespace hikari
