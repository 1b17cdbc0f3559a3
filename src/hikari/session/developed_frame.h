#pragma once
// A finished render as the image a file or a client receives: the one place that decides how a
// render becomes a picture, for `hikari render -o`, its frames and videos, and `hikari serve`.

#include <optional>
#include <variant>

#include "hikari/core/image.h"
#include "hikari/core/srgb8_encoder.h"
#include "hikari/frame/aov_picture.h"
#include "hikari/frame/tone_map.h"
#include "hikari/scene/scene.h"
#include "hikari/session/session.h"

namespace hikari {

/// How a render is developed into its output.
struct Development {
    Aov aov = Aov::color;   ///< the buffer shown
    float exposure = 0.0f;  ///< stops, applied to colour
    ToneMap tone_map = ToneMap::clamp;
    std::optional<DepthRange> depth_range;  ///< of a depth picture; default: what is visible
    /// Whether the output holds display values (PNG, JPEG, PPM, a spreadsheet, a video frame) or
    /// values to compute with (PFM, EXR): only display values are tone mapped, and only they
    /// show an AOV buffer as a picture (frame/aov_picture.h) instead of its raw values.
    bool display = true;
};

/// A developed render: 8-bit sRGB where the film already holds exactly that (nothing left to
/// develop), else float samples.
using DevelopedImage = std::variant<Srgb8Image, Image>;

/// `result` developed as `how` says: an algorithm AOV's picture as it is; an 8-bit film as it
/// is; colour exposed and (for display) tone mapped; an AOV buffer as its picture (display) or
/// its values. `scene`: the scene rendered (its infinite planes do not stretch a depth picture).
DevelopedImage develop(RenderResult&& result, const Development& how, const Scene& scene);

}  // namespace hikari
