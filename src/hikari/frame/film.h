#pragma once
// The colour output of a render: the target a method writes rows of linear RGB into. The caller
// chooses its form: linear floats, or 8-bit sRGB encoded as the rows arrive (for a PNG or PPM
// file: a quarter of the fresh memory, and no float image to encode afterwards; on a virtual
// machine the page faults of a full-HD float image cost more than encoding it).

#include <algorithm>
#include <cstddef>

#include "hikari/core/image.h"
#include "hikari/core/srgb8_encoder.h"
#include "hikari/scene/camera.h"

namespace hikari {

/// The form in which a film keeps colour.
enum class FilmFormat {
    linear,  ///< linear RGB floats (PFM, EXR, or comparing methods)
    srgb8,   ///< linear_to_srgb8 of each channel (PNG, PPM)
};

/// Row-major colour, row 0 at the top. A method writes every pixel exactly once or more: an 8-bit
/// film starts unwritten, so that its pages are first touched by the method's tiles, in parallel.
class Film {
  public:
    Film() = default;
    /// A width × height film (linear: black until written).
    Film(int width, int height, FilmFormat format) : m_format(format) {
        if (format == FilmFormat::srgb8)
            m_srgb8 = Srgb8Image(width, height);
        else
            m_linear = Image(width, height);
    }
    /// A film of the camera's image size.
    explicit Film(const Camera& camera, FilmFormat format = FilmFormat::linear)
        : Film(camera.width, camera.height, format) {}

    /// Linear or 8-bit, fixed when the film is made.
    FilmFormat format() const { return m_format; }
    /// Size in pixels.
    int width() const { return m_format == FilmFormat::srgb8 ? m_srgb8.width : m_linear.width; }
    int height() const { return m_format == FilmFormat::srgb8 ? m_srgb8.height : m_linear.height; }

    /// The colours of pixels [first, first + count) := c[0, count) (a row, or part of one).
    void set_row(size_t first, const Vec3* c, size_t count) {
        if (m_format == FilmFormat::linear) {
            std::copy_n(c, count, m_linear.pixels.begin() + static_cast<std::ptrdiff_t>(first));
            return;
        }
        const Srgb8Encoder& encoder = Srgb8Encoder::instance();
        for (size_t i = 0; i < count; ++i)
            encoder.encode(c[i], m_srgb8.bytes.data() + 3 * (first + i));
    }

    /// The same from one array per channel (a row of a renderer that keeps colours that way).
    void set_row(size_t first, const float* red, const float* green, const float* blue,
                 size_t count) {
        if (m_format == FilmFormat::linear) {
            for (size_t i = 0; i < count; ++i)
                m_linear.pixels[first + i] = Vec3(red[i], green[i], blue[i]);
            return;
        }
        Srgb8Encoder::instance().encode_row(red, green, blue, count,
                                            m_srgb8.bytes.data() + 3 * first);
    }

    /// Pixel i's colour := c.
    void set_pixel(size_t i, Vec3 c) { set_row(i, &c, 1); }

    /// The colour of a linear film (empty for an 8-bit one).
    Image& linear() { return m_linear; }
    const Image& linear() const { return m_linear; }
    /// The colour of an 8-bit film (empty for a linear one).
    const Srgb8Image& srgb8() const { return m_srgb8; }
    /// The same, to write encoded bytes into (pixels gathered from another process).
    Srgb8Image& srgb8() { return m_srgb8; }

  private:
    FilmFormat m_format = FilmFormat::linear;
    Image m_linear;
    Srgb8Image m_srgb8;
};

}  // namespace hikari
