#include "hikari/render/framebuffer.h"

#include "hikari/core/ray.h"

namespace hikari {

Framebuffer::Framebuffer(int width, int height, Vec3 background)
    : color(width, height, background),
      depth(color.pixels.size(), k_infinity),
      id(color.pixels.size(), k_background_id),
      normal(color.pixels.size(), Vec3(0.0f)) {}

Image aov_image(const Framebuffer& fb, Aov aov) {
    if (aov == Aov::color) return fb.color;
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
