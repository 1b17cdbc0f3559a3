#include "hikari/frame/framebuffer.h"

#include <stdexcept>
#include <utility>

#include "hikari/core/ray.h"

namespace hikari {

Framebuffer::Framebuffer(int width, int height, Vec3 background, bool aov_buffers,
                         bool srgb8_output) {
    if (srgb8_output)
        srgb8 = Srgb8Image(width, height);
    else
        color = Image(width, height, background);
    if (!aov_buffers) return;
    const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
    depth.assign(pixels, k_infinity);
    id.assign(pixels, k_background_id);
    normal.assign(pixels, Vec3(0.0f));
}

Image aov_image(Framebuffer&& fb, Aov aov) {
    if (aov == Aov::color) {
        if (!fb.srgb8.bytes.empty()) throw std::invalid_argument("aov_image: 8-bit colour only");
        return std::move(fb.color);
    }
    if (fb.depth.size() != fb.color.pixels.size())
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
            case Aov::color:
                break;
        }
    }
    return out;
}

}  // namespace hikari
