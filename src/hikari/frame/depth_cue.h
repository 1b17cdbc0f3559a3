#pragma once
// Depth cueing, the lecture's Fig 4.1b: far things darker and blurred (遠：暗い、ぼやけ), near
// things bright and sharp. A post step on a finished framebuffer, so every method gets it the
// same way, from its colour and its depth AOV (the eye distance of the point each pixel sees).

#include "hikari/core/vec.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// The weight of the point's own colour at eye distance `distance`:
/// w = clamp((far − d) / (far − near), 0, 1); 0 where nothing is seen (d = ∞).
float depth_cue_weight(const DepthCue& cue, float distance);

/// The blur radius in pixels at eye distance `distance`: blur · clamp((d − near) / (far − near),
/// 0, 1), growing from 0 at `near` to `blur` at `far`.
float depth_cue_blur_radius(const DepthCue& cue, float distance);

/// Blurs then blends `fb`'s colour toward the cue colour (`background` unless the cue names
/// one): colour := w·colour + (1 − w)·cue colour, w = depth_cue_weight(depth). The blur of a
/// pixel averages the pixels within its radius whose depth is similar or greater (at least 98%
/// of its own), so that a near object's edge is never smeared over what lies behind it, nor the
/// far background over it. A radius is clamped to the image's diagonal, and a disc wider than 16
/// pixels is read on a grid of at most 33 × 33 of its pixels, so no blur takes more than that
/// per pixel. `fb` must hold linear colour and the depth AOV.
void apply_depth_cue(const DepthCue& cue, Vec3 background, Framebuffer& fb);

}  // namespace hikari
