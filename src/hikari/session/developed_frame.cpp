#include "hikari/session/developed_frame.h"

namespace hikari {

DevelopedImage develop(RenderResult&& result, const Development& how, const Scene& scene) {
    if (result.algorithm_picture) return std::move(*result.algorithm_picture);
    Framebuffer& fb = result.framebuffer;
    if (fb.film.format() == FilmFormat::srgb8) return fb.film.srgb8();
    if (is_colour_aov(how.aov)) {
        Image colour = aov_image(std::move(fb), how.aov);
        expose_and_tone_map(colour, how.exposure, how.display ? how.tone_map : ToneMap::clamp);
        return colour;
    }
    if (how.display) return aov_picture(fb, how.aov, how.depth_range, unbounded_primitives(scene));
    return aov_image(std::move(fb), how.aov);
}

}  // namespace hikari
