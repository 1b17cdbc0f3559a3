#pragma once
// AOV buffers as pictures for 8-bit image files: a depth buffer of eye distances (0.3 to 40 world
// units) or a buffer of primitive ids written as they are would be a white or black rectangle.
// The float formats (.pfm, .exr) keep the raw values (frame/framebuffer.h, aov_image).

#include <cstdint>
#include <optional>
#include <span>

#include "hikari/core/image.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// Eye distances mapped to the grey range: `near` white, `far` black.
struct DepthRange {
    float near = 0.0f;
    float far = 1.0f;
};

/// The depth range of the points `fb` sees: its nearest finite depth to the farthest depth of a
/// bounded primitive (nullopt when it sees none). Pixels of the `unbounded` primitives (infinite
/// planes) set the near end but not the far one: a floor running to the horizon would otherwise
/// take the far end to thousands of units and leave the objects one flat white. With no bounded
/// primitive in view the farthest finite depth is the far end.
std::optional<DepthRange> visible_depth_range(const Framebuffer& fb,
                                              std::span<const PrimitiveId> unbounded = {});

/// The ids of the primitives of `scene` that have no extent (its infinite planes).
std::vector<PrimitiveId> unbounded_primitives(const Scene& scene);

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
///   so the nearest point is white and the farthest point of a bounded primitive black
///   (`unbounded`: the ids of infinite planes, whose far parts are black); background black;
/// - id: a false colour per primitive (hues a golden-ratio step apart, so neighbours in the
///   scene file differ), background black;
/// - normal: 0.5 + 0.5·n per channel (x red, y green, z blue), background black.
/// The framebuffer must hold the AOV buffers.
Image aov_picture(const Framebuffer& fb, Aov aov, std::optional<DepthRange> range,
                  std::span<const PrimitiveId> unbounded = {});

}  // namespace hikari
