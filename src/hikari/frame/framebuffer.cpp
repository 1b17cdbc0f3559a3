#include "hikari/frame/framebuffer.h"

#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "hikari/core/ray.h"

namespace hikari {

Framebuffer::Framebuffer(Film target, int width, int height, bool aov_buffers)
    : film(std::move(target)) {
    if (film.width() != width || film.height() != height)
        throw std::invalid_argument(fmt::format("Framebuffer: a {}x{} film for a {}x{} image",
                                                film.width(), film.height(), width, height));
    if (!aov_buffers) return;
    const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
    depth.assign(pixels, k_infinity);
    id.assign(pixels, k_background_id);
    normal.assign(pixels, Vec3(0.0f));
}

Image aov_image(Framebuffer&& fb, Aov aov) {
    if (is_colour_aov(aov)) {
        if (fb.film.format() != FilmFormat::linear)
            throw std::invalid_argument("aov_image: 8-bit colour only");
        return std::move(fb.film.linear());
    }
    const size_t pixels = static_cast<size_t>(fb.width()) * static_cast<size_t>(fb.height());
    if (fb.depth.size() != pixels)
        throw std::invalid_argument("aov_image: the render kept colour only");
    Image out(fb.width(), fb.height());
    for (size_t i = 0; i < out.pixels.size(); ++i) {
        switch (aov) {
            case Aov::depth:
                out.pixels[i] = Vec3(fb.depth[i]);
                break;
            // Ids stay exact in float up to 2^24 primitives.
            case Aov::id:
                out.pixels[i] = Vec3(static_cast<float>(fb.id[i]));
                break;
            case Aov::normal:
                out.pixels[i] = fb.normal[i];
                break;
            default:  // the colour renders, returned above
                break;
        }
    }
    return out;
}

}  // namespace hikari
