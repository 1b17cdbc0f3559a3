#pragma once
// What a method produces: colour plus auxiliary buffers (AOVs) for comparing methods.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "hikari/core/image.h"
#include "hikari/core/srgb8_encoder.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// Primitive id stored for pixels where no primitive is seen.
inline constexpr uint32_t k_background_id = 0;

/// Linear colour and per-pixel AOVs, all row-major with row 0 at the top. The AOV buffers are
/// empty when the render was asked for colour only (RenderSettings::aov_buffers false).
struct Framebuffer {
    Image color;  ///< linear RGB; empty when the method filled `srgb8` instead
    /// The colour as 8-bit sRGB, set pixel by pixel instead of `color` by a method that honours
    /// RenderSettings::srgb8_output (a quarter of the memory); else empty.
    Srgb8Image srgb8;
    HugePageVector<float> depth;  ///< eye-space distance to the surface seen at the pixel centre;
                                  ///< infinity for background
    HugePageVector<uint32_t>
        id;  ///< 1 + PrimitiveId seen at the pixel centre, k_background_id for none
    HugePageVector<Vec3> normal;  ///< unit world-space shading normal at the pixel centre facing
                                  ///< the eye; zero for background

    Framebuffer() = default;
    /// Colour filled with `background`, or with `srgb8_output` 8-bit colour (`srgb8`) left
    /// unwritten, for a method that sets every pixel (`color` then stays empty); the AOV buffers
    /// cleared to "nothing seen" when `aov_buffers`, else left empty.
    Framebuffer(int width, int height, Vec3 background, bool aov_buffers = true,
                bool srgb8_output = false);

    int width() const { return srgb8.bytes.empty() ? color.width : srgb8.width; }
    int height() const { return srgb8.bytes.empty() ? color.height : srgb8.height; }
    /// The colours of pixels [first, first + count) := c[0, count) (a row, or part of one).
    void set_colors(size_t first, const Vec3* c, size_t count) {
        if (srgb8.bytes.empty()) {
            std::copy_n(c, count, color.pixels.begin() + static_cast<std::ptrdiff_t>(first));
            return;
        }
        const Srgb8Encoder& encoder = Srgb8Encoder::instance();
        for (size_t i = 0; i < count; ++i)
            encoder.encode(c[i], srgb8.bytes.data() + 3 * (first + i));
    }

    /// The same from one array per channel (a row of a renderer that keeps colours that way).
    void set_colors(size_t first, const float* red, const float* green, const float* blue,
                    size_t count) {
        if (srgb8.bytes.empty()) {
            for (size_t i = 0; i < count; ++i)
                color.pixels[first + i] = Vec3(red[i], green[i], blue[i]);
            return;
        }
        Srgb8Encoder::instance().encode_row(red, green, blue, count,
                                            srgb8.bytes.data() + 3 * first);
    }

    /// Pixel i's colour := c (in whichever form the framebuffer keeps it).
    void set_color(size_t i, Vec3 c) { set_colors(i, &c, 1); }
};

/// Which buffer an image file receives.
enum class Aov { color, depth, id, normal };

/// The chosen buffer as an RGB image (depth and id repeated in every channel, exactly). The
/// framebuffer must hold that buffer (for colour: `color`, not only `srgb8`). Moves the colour out
/// rather than copying it.
Image aov_image(Framebuffer&& fb, Aov aov);

}  // namespace hikari
