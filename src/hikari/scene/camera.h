#pragma once
// The pinhole camera of the lecture's ray tracer and of the rasterizer's view transform.

#include "hikari/core/mat4.h"
#include "hikari/core/ray.h"

namespace hikari {

/// A pinhole camera as the scene file describes it.
struct Camera {
    Vec3 eye{0, 0, 0};
    Vec3 look_at{0, 0, -1};
    Vec3 up{0, 1, 0};
    float fov_y_degrees = 60.0f;  ///< vertical field of view
    int width = 512;              ///< image width in pixels
    int height = 512;             ///< image height in pixels
};

/// The camera's orthonormal frame, precomputed once per render.
struct CameraFrame {
    Vec3 eye, right, up, forward;  ///< right-handed: forward = -w, right = u, up = v
    float tan_half_fov_y = 0;
    float aspect = 1;  ///< width / height
    int width = 0, height = 0;
};

CameraFrame make_camera_frame(const Camera& camera);

/// The ray from the eye through image-plane point (sx, sy) on the plane one unit in front of
/// the eye, where (sx, sy) are in pixel units: (0, 0) is the top-left corner of the image and
/// (i + 0.5, j + 0.5) the centre of pixel (i, j), row j counted from the top.
inline Ray camera_ray(const CameraFrame& f, float px, float py) {
    const float x = (2.0f * px / static_cast<float>(f.width) - 1.0f) * f.tan_half_fov_y * f.aspect;
    const float y = (1.0f - 2.0f * py / static_cast<float>(f.height)) * f.tan_half_fov_y;
    return {f.eye, normalize(f.forward + x * f.right + y * f.up)};
}

/// view_from_world of the camera (OpenGL convention: looks down -z).
Mat4 view_matrix(const Camera& camera);

}  // namespace hikari
