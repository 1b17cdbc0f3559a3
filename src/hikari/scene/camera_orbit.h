#pragma once
// A turntable: the camera carried around the point it looks at, as a model is shown on a
// potter's wheel. The eye turns about the axis through look_at along the camera's up vector, so
// its height above look_at (the elevation) and its distance from it (the radius) stay those of
// the camera it starts from.

#include "hikari/scene/camera.h"

namespace hikari {

/// `camera` with its eye turned by `turns` of a full circle (counter-clockwise seen from above,
/// that is from the tip of `up`) about the axis through look_at along up; look_at, up, the
/// projection and the image size unchanged. Computed in double precision from the camera's own
/// values, so a frame's camera does not depend on the frames before it.
Camera orbited_camera(const Camera& camera, double turns);

/// Frame `frame` (0 to frame_count − 1) of a `frame_count`-frame turntable of `camera`: turned by
/// frame / frame_count turns. Frame 0 is `camera` itself, bit for bit.
Camera turntable_camera(const Camera& camera, int frame, int frame_count);

}  // namespace hikari
