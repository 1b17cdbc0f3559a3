#include "hikari/frame/depth_cue.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <tbb/blocked_range.h>

#include "hikari/core/parallel.h"

namespace hikari {

namespace {

/// (d − near) / (far − near) clamped to [0, 1]: 0 at near, 1 at far and beyond (also at ∞).
float depth_fraction(const DepthCue& cue, float distance) {
    if (!(distance < INFINITY)) return 1.0f;
    return std::clamp((distance - cue.near) / (cue.far - cue.near), 0.0f, 1.0f);
}

/// Pixel (x, y) of `source` averaged over the disc of `radius` pixels around it, taking only the
/// pixels at depth `min_depth` or more.
Vec3 gather(const Image& source, const HugePageVector<float>& depth, int x, int y, float radius,
            float min_depth) {
    const int reach = static_cast<int>(std::ceil(radius));
    const float r2 = radius * radius;
    Vec3 sum(0.0f);
    int count = 0;
    for (int v = std::max(0, y - reach); v <= std::min(source.height - 1, y + reach); ++v)
        for (int u = std::max(0, x - reach); u <= std::min(source.width - 1, x + reach); ++u) {
            const float du = static_cast<float>(u - x), dv = static_cast<float>(v - y);
            const size_t q = static_cast<size_t>(v) * source.width + u;
            if (du * du + dv * dv > r2 || !(depth[q] >= min_depth)) continue;
            sum += source.pixels[q];
            ++count;
        }
    return count > 0 ? sum / static_cast<float>(count) : source.at(x, y);
}

/// The blurred colour of every pixel, from a copy of the unblurred image.
void blur(const DepthCue& cue, Framebuffer& fb) {
    const Image source = fb.film.linear();
    Image& target = fb.film.linear();
    hikari::parallel_for(
        tbb::blocked_range<int>(0, source.height), [&](const tbb::blocked_range<int>& rows) {
            for (int y = rows.begin(); y != rows.end(); ++y)
                for (int x = 0; x < source.width; ++x) {
                    const size_t i = static_cast<size_t>(y) * source.width + x;
                    const float radius = depth_cue_blur_radius(cue, fb.depth[i]);
                    if (radius < 0.5f) continue;  // the nearest pixel only: nothing to average
                    target.pixels[i] = gather(source, fb.depth, x, y, radius, 0.98f * fb.depth[i]);
                }
        });
}

}  // namespace

float depth_cue_weight(const DepthCue& cue, float distance) {
    return std::clamp((cue.far - distance) / (cue.far - cue.near), 0.0f, 1.0f);
}

float depth_cue_blur_radius(const DepthCue& cue, float distance) {
    return cue.blur * depth_fraction(cue, distance);
}

void apply_depth_cue(const DepthCue& cue, Vec3 background, Framebuffer& fb) {
    Image& colour = fb.film.linear();
    if (colour.pixels.size() != fb.depth.size())
        throw std::logic_error("depth cueing needs linear colour and the depth AOV");
    if (cue.blur > 0.0f) blur(cue, fb);
    const Vec3 c = cue.color.value_or(background);
    hikari::parallel_for(tbb::blocked_range<size_t>(0, colour.pixels.size()),
                         [&](const tbb::blocked_range<size_t>& range) {
                             for (size_t i = range.begin(); i != range.end(); ++i) {
                                 const float w = depth_cue_weight(cue, fb.depth[i]);
                                 colour.pixels[i] = w * colour.pixels[i] + (1.0f - w) * c;
                             }
                         });
}

}  // namespace hikari
