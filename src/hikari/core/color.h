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

/// Linear value to an 8-bit sRGB code value, rounded to nearest.
inline uint8_t linear_to_srgb8(float v) {
    return static_cast<uint8_t>(std::lround(linear_to_srgb(v) * 255.0f));
}

}  // namespace hikari
