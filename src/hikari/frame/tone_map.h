#pragma once
// Exposure and tone mapping: how a linear render is developed into a picture for a display.
// Applied to a copy of the colour on its way to a file; the render itself stays linear.

#include "hikari/core/image.h"

namespace hikari {

/// The operator that brings linear radiance into the [0, 1] a display (and an 8-bit file) holds.
enum class ToneMap {
    clamp,     ///< none: values above 1 clip to white when encoded (hikari's default)
    reinhard,  ///< c / (1 + c) per channel
    aces,      ///< Narkowicz's fit of the ACES filmic curve, per channel
};

/// `c` (one linear channel value) through `op`. clamp returns `c` unchanged (the encoder
/// clamps); reinhard and aces return a value in [0, 1], 0 for a negative value or NaN, 1 for
/// +infinity.
float tone_map(float c, ToneMap op);

/// Every channel of `image` multiplied by 2^exposure_ev (photographic stops), then through `op`.
/// exposure 0 with clamp leaves the image exactly as it was.
void expose_and_tone_map(Image& image, float exposure_ev, ToneMap op);

}  // namespace hikari
