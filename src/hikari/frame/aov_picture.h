#pragma once
// AOV buffers as pictures for 8-bit image files: a depth buffer of eye distances (0.3 to 40 world
// units) or a buffer of primitive ids written as they are would be a white or black rectangle.
// The float formats (.pfm, .exr) keep the raw values (frame/framebuffer.h, aov_image).

#include <cstdint>
#include <optional>

#include "hikari/core/image.h"
#include "hikari/frame/framebuffer.h"

namespace hikari {

/// Eye distances mapped to the grey range: `near` white, `far` black.
struct DepthRange {
    float near = 0.0f;
    float far = 1.0f;
};

/// The depth range of the points `fb` sees: its nearest and farthest finite depths (nullopt
/// when it sees none).
std::optional<DepthRange> visible_depth_range(const Framebuffer& fb);

/// A colour ramp for counts and orders, t in [0, 1]: dark blue, through green and yellow, to
/// white (display values).
Vec3 ramp_colour(float t);

/// A saturated false colour for index `i` (hues a golden-ratio step apart, so neighbours differ;
/// display values).
Vec3 index_colour(uint32_t i);

/// The buffer `aov` (depth, id or normal) of `fb` as a picture whose 8-bit sRGB encoding holds
/// the display values:
/// - depth: grey 1 − (d − near)/(far − near), clamped to [0, 1] — near white, far black (the
///   Z-buffer of Fig 4.14 read as "brighter is nearer"); `range` defaults to the visible range,
///   so the nearest point is white and the farthest black; background (d = ∞) black;
/// - id: a false colour per primitive (hues a golden-ratio step apart, so neighbours in the
///   scene file differ), background black;
/// - normal: 0.5 + 0.5·n per channel (x red, y green, z blue), background black.
/// The framebuffer must hold the AOV buffers.
Image aov_picture(const Framebuffer& fb, Aov aov, std::optional<DepthRange> range);

}  // namespace hikari
