#include "hikari/frame/line_drawing.h"

#include <algorithm>
#include <cmath>

#include "hikari/frame/depth_cue.h"

namespace hikari {

float segment_length(const LineSegment& seg) {
    return std::hypot(seg.b.x - seg.a.x, seg.b.y - seg.a.y);
}

LineSegment sub_segment(const LineSegment& seg, float s0, float s1) {
    LineSegment out = seg;
    out.a = segment_point(seg, s0);
    out.b = segment_point(seg, s1);
    out.inv_w_a = (1.0f - s0) * seg.inv_w_a + s0 * seg.inv_w_b;
    out.inv_w_b = (1.0f - s1) * seg.inv_w_a + s1 * seg.inv_w_b;
    out.world_a = segment_world_point(seg, s0);
    out.world_b = segment_world_point(seg, s1);
    return out;
}

LineDrawing depth_cued(const LineDrawing& drawing, const DepthCue& cue) {
    constexpr float k_max_weight_step = 1.0f / 128.0f;
    constexpr int k_max_pieces = 256;
    const Vec3 cue_color = cue.color.value_or(drawing.background);
    LineDrawing out = drawing;
    out.background = cue_color;
    out.segments.clear();
    auto weight = [&](const LineSegment& seg, float s) {
        return depth_cue_weight(cue, length(segment_world_point(seg, s) - drawing.eye));
    };
    for (const LineSegment& seg : drawing.segments) {
        // The weight is a clamped affine function of the distance, which is convex along the
        // segment: its ends and midpoint bound how much it changes.
        const float w0 = weight(seg, 0.0f), w1 = weight(seg, 0.5f), w2 = weight(seg, 1.0f);
        const float change = std::max({std::abs(w1 - w0), std::abs(w2 - w1), std::abs(w2 - w0)});
        const int pieces = std::clamp(
            static_cast<int>(std::ceil(2.0f * change / k_max_weight_step)), 1, k_max_pieces);
        for (int k = 0; k < pieces; ++k) {
            const float s0 = float(k) / float(pieces), s1 = float(k + 1) / float(pieces);
            LineSegment piece = pieces == 1 ? seg : sub_segment(seg, s0, s1);
            const float w = weight(seg, 0.5f * (s0 + s1));
            piece.color = w * seg.color + (1.0f - w) * cue_color;
            out.segments.push_back(piece);
        }
    }
    return out;
}

}  // namespace hikari
