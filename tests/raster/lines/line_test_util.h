#pragma once
// Helpers shared by the line-drawing tests: boxes as OBJ quads, and an independent projection
// of world points to pixels (from the camera's frame, not the raster pipeline's matrices).

#include <cmath>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "hikari/frame/line_drawing.h"
#include "hikari/scene/camera.h"

namespace hikari::testing {

/// An axis-aligned box from `lo` to `hi` as an OBJ of six quads, wound outward.
inline std::string box_obj(Vec3 lo, Vec3 hi) {
    std::string s;
    for (int k = 0; k < 8; ++k)
        s += fmt::format("v {} {} {}\n", (k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y,
                         (k & 4) ? hi.z : lo.z);
    // Corner k has bits x = 1, y = 2, z = 4; OBJ numbers from 1.
    s += "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
    return s;
}

/// The twelve edges of the box from `lo` to `hi`, as pairs of corners.
struct BoxEdge {
    Vec3 p, q;
    int axis;  ///< the axis the edge runs along
};
inline std::vector<BoxEdge> box_edges(Vec3 lo, Vec3 hi) {
    std::vector<BoxEdge> edges;
    for (int axis = 0; axis < 3; ++axis)
        for (int k = 0; k < 4; ++k) {
            Vec3 p, q;
            const int a = (axis + 1) % 3, b = (axis + 2) % 3;
            p[axis] = lo[axis];
            q[axis] = hi[axis];
            p[a] = q[a] = (k & 1) ? hi[a] : lo[a];
            p[b] = q[b] = (k & 2) ? hi[b] : lo[b];
            edges.push_back({p, q, axis});
        }
    return edges;
}

/// The pixel position of world point `p` seen by `camera` (y down, pixel centres at +0.5).
inline Vec2 pixel_of(const Camera& camera, Vec3 p) {
    const CameraFrame f = make_camera_frame(camera);
    const Vec3 d = p - f.eye;
    const float z = dot(d, f.forward);
    const float x_ndc = dot(d, f.right) / z / (f.tan_half_fov_y * f.aspect);
    const float y_ndc = dot(d, f.up) / z / f.tan_half_fov_y;
    return {0.5f * (x_ndc + 1.0f) * float(camera.width),
            0.5f * (1.0f - y_ndc) * float(camera.height)};
}

inline float pixel_distance(Vec2 a, Vec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

/// Distance in pixels from `p` to the segment (a, b).
inline float distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
    const float dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
    float t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0f;
    t = std::clamp(t, 0.0f, 1.0f);
    return pixel_distance(p, {a.x + t * dx, a.y + t * dy});
}

/// Total length in pixels of the drawing's segments.
inline double total_length(const LineDrawing& d) {
    double sum = 0;
    for (const LineSegment& s : d.segments) sum += segment_length(s);
    return sum;
}

}  // namespace hikari::testing
