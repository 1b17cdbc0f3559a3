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

/// The most pixels a gather reads along each direction from its centre: a wider disc is read
/// on a grid of every step-th pixel (step = ⌈reach / k_gather_reach⌉), so the cost per pixel
/// stays below (2 · 16 + 1)² reads however wide the blur; discs up to 16 pixels are read whole.
constexpr int k_gather_reach = 16;

/// Pixel (x, y) of `source` averaged over the disc of `radius` pixels around it, taking only the
/// pixels at depth `min_depth` or more (wide discs on a grid, k_gather_reach).
Vec3 gather(const Image& source, const HugePageVector<float>& depth, int x, int y, float radius,
            float min_depth) {
    const int reach = static_cast<int>(std::ceil(radius));
    const int step = (reach + k_gather_reach - 1) / k_gather_reach;
    const int steps = reach / step;
    const float r2 = radius * radius;
    Vec3 sum(0.0f);
    int count = 0;
    for (int j = -std::min(steps, y / step); j <= std::min(steps, (source.height - 1 - y) / step);
         ++j)
        for (int i = -std::min(steps, x / step);
             i <= std::min(steps, (source.width - 1 - x) / step); ++i) {
            const int u = x + i * step, v = y + j * step;
            const float du = static_cast<float>(u - x), dv = static_cast<float>(v - y);
            const size_t q = static_cast<size_t>(v) * source.width + u;
            if (du * du + dv * dv > r2 || !(depth[q] >= min_depth)) continue;
            sum += source.pixels[q];
            ++count;
        }
    return count > 0 ? sum / static_cast<float>(count) : source.at(x, y);
}

/// The blurred colour of every pixel, from a copy of the unblurred image. A radius beyond the
/// image's diagonal reads no more pixels than the diagonal: it is clamped there.
void blur(const DepthCue& cue, Framebuffer& fb) {
    const Image source = fb.film.linear();
    Image& target = fb.film.linear();
    const float diagonal =
        std::hypot(static_cast<float>(source.width), static_cast<float>(source.height));
    hikari::parallel_for(
        tbb::blocked_range<int>(0, source.height), [&](const tbb::blocked_range<int>& rows) {
            for (int y = rows.begin(); y != rows.end(); ++y)
                for (int x = 0; x < source.width; ++x) {
                    const size_t i = static_cast<size_t>(y) * source.width + x;
                    const float radius =
                        std::min(depth_cue_blur_radius(cue, fb.depth[i]), diagonal);
                    if (!(radius >= 0.5f)) continue;  // the nearest pixel only: nothing to average
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
