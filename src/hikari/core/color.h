#pragma once
// Colour encodings at the edges of the pipeline: all rendering is in linear RGB.

#include <cmath>
#include <cstdint>

#include "hikari/core/vec.h"

namespace hikari {

/// The luminance Y of linear RGB with the Rec. 709 (sRGB) primaries.
inline float luminance(Vec3 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

/// Linear [0, 1] to the sRGB transfer curve (IEC 61966-2-1); values outside are clamped.
inline float linear_to_srgb(float v) {
    if (!(v > 0.0f)) return 0.0f;  // also maps NaN to 0
    if (v >= 1.0f) return 1.0f;
    return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

/// sRGB-encoded [0, 1] back to linear.
inline float srgb_to_linear(float v) {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

/// `c` with each channel sRGB-encoded (clamped to [0, 1]).
inline Vec3 encode_srgb(Vec3 c) {
    return {linear_to_srgb(c.x), linear_to_srgb(c.y), linear_to_srgb(c.z)};
}

/// `c` (sRGB-encoded) with each channel decoded to linear: also the linear value that the 8-bit
/// writers turn back into the display value c, so a picture made of display values keeps its
/// steps in the file's bytes.
inline Vec3 decode_srgb(Vec3 c) {
    return {srgb_to_linear(c.x), srgb_to_linear(c.y), srgb_to_linear(c.z)};
}

/// Linear value to an 8-bit sRGB code value, rounded to nearest.
inline uint8_t linear_to_srgb8(float v) {
    return static_cast<uint8_t>(std::lround(linear_to_srgb(v) * 255.0f));
}

}  // namespace hikari
