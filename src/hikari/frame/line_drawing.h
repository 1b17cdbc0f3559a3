#pragma once
// A line drawing (the lecture's Fig 4.1a, c): what the line methods produce before it becomes
// pixels or an SVG file. Resolution-independent segments in pixel coordinates, each with its
// world-space ends so that its depth, and so its depth cue, is known along it.

#include <vector>

#include "hikari/core/vec.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// A straight visible piece of an edge, already clipped to the view.
struct LineSegment {
    Vec2 a, b;              ///< ends in pixels, (0, 0) the image's top-left corner, y down
    float inv_w_a = 1;      ///< 1 / view depth at a (affine along the projected segment)
    float inv_w_b = 1;      ///< 1 / view depth at b
    Vec3 world_a, world_b;  ///< the same ends in world space
    Vec3 color{1.0f};       ///< linear RGB
    PrimitiveId id = 0;     ///< the primitive whose edge this is
};

/// The segments of one drawing, in a deterministic order, and how to draw them.
struct LineDrawing {
    int width = 0, height = 0;  ///< image size in pixels
    float line_width = 1;       ///< stroke width in pixels
    CameraFrame camera;         ///< the camera (depth is camera_distance)
    Vec3 background{0.0f};      ///< linear RGB behind the lines
    std::vector<LineSegment> segments;
};

/// The world-space point of `seg` at screen parameter s ∈ [0, 1] (s = 0 at a, 1 at b), found
/// perspective-correctly: 1 / w is affine in s, the world point affine in t.
inline Vec3 segment_world_point(const LineSegment& seg, float s) {
    const float denominator = (1.0f - s) * seg.inv_w_a + s * seg.inv_w_b;
    const float t = denominator > 0.0f ? s * seg.inv_w_b / denominator : s;
    return seg.world_a + (seg.world_b - seg.world_a) * t;
}

/// The pixel position of `seg` at screen parameter s.
inline Vec2 segment_point(const LineSegment& seg, float s) {
    return {seg.a.x + (seg.b.x - seg.a.x) * s, seg.a.y + (seg.b.y - seg.a.y) * s};
}

/// Length of `seg` in pixels.
float segment_length(const LineSegment& seg);

/// The part of `seg` between screen parameters s0 and s1, as a segment of its own.
LineSegment sub_segment(const LineSegment& seg, float s0, float s1);

/// The drawing as depth cueing (Fig 4.1b, frame/depth_cue.h) shows it: every segment split
/// into pieces short enough that the cue weight changes by about 1/128 along one, each piece
/// coloured w·colour + (1 − w)·cue colour at its midpoint's eye distance; the background, at
/// infinite distance, becomes the cue colour. (The cue's blur has no vector form and is left
/// out.)
LineDrawing depth_cued(const LineDrawing& drawing, const DepthCue& cue);

}  // namespace hikari
