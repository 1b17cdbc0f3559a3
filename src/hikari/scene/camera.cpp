#include "hikari/scene/camera.h"

#include <cmath>
#include <numbers>

namespace hikari {

CameraFrame make_camera_frame(const Camera& camera) {
    CameraFrame f;
    f.eye = camera.eye;
    f.forward = normalize(camera.look_at - camera.eye);
    f.right = normalize(cross(f.forward, camera.up));
    f.up = cross(f.right, f.forward);
    f.orthographic = camera.projection == Projection::orthographic;
    f.tan_half_fov_y =
        f.orthographic
            ? 0.5f * camera.view_height
            : static_cast<float>(std::tan(camera.fov_y_degrees * std::numbers::pi / 360.0));
    f.aspect = static_cast<float>(camera.width) / static_cast<float>(camera.height);
    f.width = camera.width;
    f.height = camera.height;
    return f;
}

const char* camera_view_fault(const Camera& camera) {
    const Vec3 view = camera.look_at - camera.eye;
    if (!(dot(view, view) > 0.0f)) return "eye and look_at are the same point";
    const Vec3 side = cross(normalize(view), normalize(camera.up));
    if (!(dot(side, side) >= 1e-10f)) return "up is parallel to the view direction";
    return nullptr;
}

Mat4 view_matrix(const Camera& camera) { return look_at(camera.eye, camera.look_at, camera.up); }

}  // namespace hikari
