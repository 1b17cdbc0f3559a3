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

namespace {

/// The screen parameter of `seg` at world parameter t (the inverse of segment_world_point's
/// mapping: w is affine in t).
float screen_parameter(const LineSegment& seg, float t) {
    const float denominator = (1.0f - t) * seg.inv_w_b + t * seg.inv_w_a;
    return denominator > 0.0f ? t * seg.inv_w_a / denominator : t;
}

/// Appends the pieces of `seg` between world parameters t0 and t1 (weights w0, w1 there),
/// halving until the cue weight changes by at most `step` along a piece.
template <class Weight>
void split_by_weight(const LineSegment& seg, float t0, float t1, float w0, float w1,
                     const Weight& weight, float step, int depth, std::vector<float>& cuts) {
    const float tm = 0.5f * (t0 + t1), wm = weight(tm);
    const bool flat = std::abs(w1 - w0) <= step && std::abs(wm - 0.5f * (w0 + w1)) <= 0.5f * step;
    if (flat || depth == 0) {
        cuts.push_back(t1);
        return;
    }
    split_by_weight(seg, t0, tm, w0, wm, weight, step, depth - 1, cuts);
    split_by_weight(seg, tm, t1, wm, w1, weight, step, depth - 1, cuts);
}

}  // namespace

LineDrawing depth_cued(const LineDrawing& drawing, const DepthCue& cue) {
    constexpr float k_max_weight_step = 1.0f / 128.0f;
    constexpr int k_max_halvings = 12;
    const Vec3 cue_color = cue.color.value_or(drawing.background);
    LineDrawing out = drawing;
    out.background = cue_color;
    out.segments.clear();
    std::vector<float> cuts;
    for (const LineSegment& seg : drawing.segments) {
        // The weight is a clamped affine function of the eye distance, which along the segment
        // is a convex function of the world parameter t: halving finds where it bends.
        auto weight = [&](float t) {
            const Vec3 p = seg.world_a + (seg.world_b - seg.world_a) * t;
            return depth_cue_weight(cue, camera_distance(drawing.camera, p));
        };
        cuts.assign(1, 0.0f);
        split_by_weight(seg, 0.0f, 1.0f, weight(0.0f), weight(1.0f), weight, k_max_weight_step,
                        k_max_halvings, cuts);
        for (size_t k = 0; k + 1 < cuts.size(); ++k) {
            const float s0 = screen_parameter(seg, cuts[k]);
            const float s1 = screen_parameter(seg, cuts[k + 1]);
            LineSegment piece = cuts.size() == 2 ? seg : sub_segment(seg, s0, s1);
            const float w = weight(0.5f * (cuts[k] + cuts[k + 1]));
            piece.color = w * seg.color + (1.0f - w) * cue_color;
            out.segments.push_back(piece);
        }
    }
    return out;
}

}  // namespace hikari
