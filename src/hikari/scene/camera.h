#pragma once
// The camera of the lecture's ray tracer and of the rasterizer's view transform: a pinhole
// (perspective projection, 透視投影) or a parallel projection (orthographic).

#include "hikari/core/mat4.h"
#include "hikari/core/ray.h"

namespace hikari {

/// How the camera maps the world onto the image.
enum class Projection {
    perspective,   ///< rays from the eye through the image plane (a pinhole)
    orthographic,  ///< parallel rays along the view direction, from the plane through the eye
};

/// A camera as the scene file describes it.
struct Camera {
    Vec3 eye{0, 0, 0};
    Vec3 look_at{0, 0, -1};
    Vec3 up{0, 1, 0};
    Projection projection = Projection::perspective;
    float fov_y_degrees = 60.0f;  ///< perspective: vertical field of view
    float view_height = 2.0f;     ///< orthographic: world units the image spans vertically
    int width = 512;              ///< image width in pixels
    int height = 512;             ///< image height in pixels
};

/// The camera's orthonormal frame, precomputed once per render.
struct CameraFrame {
    Vec3 eye, right, up, forward;  ///< right-handed: forward = -w, right = u, up = v
    /// Perspective: tan(fov_y / 2), the image plane's half height one unit in front of the eye.
    /// Orthographic: half the view height, in world units.
    float tan_half_fov_y = 0;
    float aspect = 1;  ///< width / height
    int width = 0, height = 0;
    bool orthographic = false;
};

CameraFrame make_camera_frame(const Camera& camera);

/// Why `camera`'s eye, look_at and up make no view (a view direction of zero length, or an up
/// parallel to it, leave the camera frame undefined), or nullptr when they make one. Every
/// front end that takes a camera (scene files, Python, HTTP requests) asks this one question.
const char* camera_view_fault(const Camera& camera);

/// The camera ray through image point (px, py) in pixel units: (0, 0) is the top-left corner of
/// the image and (i + 0.5, j + 0.5) the centre of pixel (i, j), row j counted from the top.
/// Perspective: from the eye through x·right + y·up + forward on the plane one unit in front of
/// it. Orthographic: from eye + x·right + y·up (on the plane through the eye) along forward.
/// x = (2px/W − 1)·h·W/H and y = (1 − 2py/H)·h, h = tan_half_fov_y.
HIKARI_HD inline Ray camera_ray(const CameraFrame& f, float px, float py) {
    const float x = (2.0f * px / static_cast<float>(f.width) - 1.0f) * f.tan_half_fov_y * f.aspect;
    const float y = (1.0f - 2.0f * py / static_cast<float>(f.height)) * f.tan_half_fov_y;
    if (f.orthographic) return {f.eye + x * f.right + y * f.up, f.forward};
    return {f.eye, normalize(f.forward + x * f.right + y * f.up)};
}

/// The distance at which the camera ray that reaches world point `p` meets it (the depth AOV):
/// from the eye (perspective), or from the plane through the eye (orthographic).
HIKARI_HD inline float camera_distance(const CameraFrame& f, Vec3 p) {
    return f.orthographic ? dot(p - f.eye, f.forward) : length(p - f.eye);
}

/// The unit vector from world point `p` toward the viewer (V of the shading model).
HIKARI_HD inline Vec3 toward_viewer(const CameraFrame& f, Vec3 p) {
    return f.orthographic ? -f.forward : normalize(f.eye - p);
}

/// view_from_world of the camera (OpenGL convention: looks down -z).
Mat4 view_matrix(const Camera& camera);

}  // namespace hikari
