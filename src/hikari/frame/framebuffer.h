#pragma once
// What a method produces: colour (in the film the caller chose) plus auxiliary buffers (AOVs) for
// comparing methods.

#include <cstddef>
#include <cstdint>

#include "hikari/core/image.h"
#include "hikari/frame/film.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// Primitive id stored for pixels where no primitive is seen.
inline constexpr uint32_t k_background_id = 0;

/// A film and per-pixel AOVs, all row-major with row 0 at the top. The AOV buffers are empty when
/// the render was asked for colour only (RenderSettings::aov_buffers false).
struct Framebuffer {
    Film film;                    ///< colour, linear or 8-bit as the caller chose
    HugePageVector<float> depth;  ///< eye-space distance to the surface seen at the pixel centre;
                                  ///< infinity for background
    HugePageVector<uint32_t>
        id;  ///< 1 + PrimitiveId seen at the pixel centre, k_background_id for none
    HugePageVector<Vec3> normal;  ///< unit world-space shading normal at the pixel centre facing
                                  ///< the eye; zero for background

    Framebuffer() = default;
    /// `target`, which the method then fills, and the AOV buffers cleared to "nothing seen" when
    /// `aov_buffers`, else left empty. Throws std::invalid_argument unless the film is
    /// width × height (the camera's image size).
    Framebuffer(Film target, int width, int height, bool aov_buffers);

    int width() const { return film.width(); }
    int height() const { return film.height(); }
    /// The colours of pixels [first, first + count) := c[0, count): Film::set_row.
    void set_colors(size_t first, const Vec3* c, size_t count) { film.set_row(first, c, count); }
    /// The same from one array per channel: Film::set_row.
    void set_colors(size_t first, const float* red, const float* green, const float* blue,
                    size_t count) {
        film.set_row(first, red, green, blue, count);
    }
    /// Pixel i's colour := c: Film::set_pixel.
    void set_color(size_t i, Vec3 c) { film.set_pixel(i, c); }
};

/// Which buffer an image file receives: the colour, an AOV buffer, or the colour of one term of
/// the shading model alone (ambient, diffuse, specular: a colour render of the scene that
/// shading/shading_terms.h changed).
/// The last four show an algorithm at work rather than a buffer every method fills (see
/// explain/algorithm_aovs.h).
enum class Aov {
    color,
    depth,
    id,
    normal,
    ambient,
    diffuse,
    specular,
    overdraw,
    paint_order,
    spans,
    culled
};

/// Whether `aov` shows an algorithm's work (overdraw, paint-order, spans, culled).
constexpr bool is_algorithm_aov(Aov aov) {
    return aov == Aov::overdraw || aov == Aov::paint_order || aov == Aov::spans ||
           aov == Aov::culled;
}

/// Whether `aov`'s raw values are one number per pixel (a count or a painting position), held
/// in every channel of an algorithm AOV image.
constexpr bool is_count_aov(Aov aov) { return aov == Aov::overdraw || aov == Aov::paint_order; }

/// Whether `aov` is a colour render (the full colour or one shading term), not an AOV buffer.
constexpr bool is_colour_aov(Aov aov) {
    return aov == Aov::color || aov == Aov::ambient || aov == Aov::diffuse || aov == Aov::specular;
}

/// The chosen buffer as an RGB image (depth and id repeated in every channel, exactly). The
/// framebuffer must hold that buffer (for a colour render: a linear film). Moves the colour out
/// rather than copying it.
Image aov_image(Framebuffer&& fb, Aov aov);

}  // namespace hikari
