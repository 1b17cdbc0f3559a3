// A render developed into its output (session/developed_frame.h): the one decision behind
// `hikari render -o`, its frames and `hikari serve`'s pictures.
#include "hikari/session/developed_frame.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace hikari {
namespace {

RenderResult whitted_render(Aov aov, FilmFormat film = FilmFormat::linear) {
    Session session({.file = std::string(HIKARI_SOURCE_DIR) + "/scenes/whitted.json"});
    RenderRequest request;
    request.method = "zbuffer";
    request.width = 48;
    request.height = 36;
    request.aov = aov;
    request.film = film;
    return session.render(request);
}

const Scene& whitted_scene() {
    static Session session({.file = std::string(HIKARI_SOURCE_DIR) + "/scenes/whitted.json"});
    return session.scene();
}

TEST(DevelopedFrame, ValuesKeepRadianceAndDisplayIsToneMapped) {
    const Image linear = std::get<Image>(develop(whitted_render(Aov::color), {}, whitted_scene()));
    const Development values{.exposure = 1.0f, .tone_map = ToneMap::reinhard, .display = false};
    const Image exposed =
        std::get<Image>(develop(whitted_render(Aov::color), values, whitted_scene()));
    Development display = values;
    display.display = true;
    const Image mapped =
        std::get<Image>(develop(whitted_render(Aov::color), display, whitted_scene()));
    ASSERT_EQ(exposed.pixels.size(), linear.pixels.size());
    bool any_lit = false;
    for (size_t i = 0; i < linear.pixels.size(); ++i) {
        const float c = linear.pixels[i].x;
        EXPECT_FLOAT_EQ(exposed.pixels[i].x, 2.0f * c) << i;  // one stop, no tone map
        EXPECT_NEAR(mapped.pixels[i].x, 2.0f * c / (1.0f + 2.0f * c), 1e-6f) << i;
        any_lit = any_lit || c > 0.1f;
    }
    EXPECT_TRUE(any_lit);
}

TEST(DevelopedFrame, AnAovIsAPictureForDisplayAndItsValuesOtherwise) {
    RenderResult result = whitted_render(Aov::depth);
    const std::vector<float> depth(result.framebuffer.depth.begin(),
                                   result.framebuffer.depth.end());
    const Image values = std::get<Image>(develop(
        whitted_render(Aov::depth), {.aov = Aov::depth, .display = false}, whitted_scene()));
    const Image picture =
        std::get<Image>(develop(std::move(result), {.aov = Aov::depth}, whitted_scene()));
    bool far_seen = false;
    for (size_t i = 0; i < depth.size(); ++i) {
        EXPECT_EQ(values.pixels[i].x, depth[i]) << i;
        EXPECT_GE(picture.pixels[i].x, 0.0f);
        EXPECT_LE(picture.pixels[i].x, 1.0f);
        far_seen = far_seen || (std::isfinite(depth[i]) && depth[i] > 1.0f);
    }
    EXPECT_TRUE(far_seen);
}

TEST(DevelopedFrame, AnEightBitFilmIsTakenAsItIs) {
    RenderResult result = whitted_render(Aov::color, FilmFormat::srgb8);
    const Srgb8Image film = result.framebuffer.film.srgb8();
    const DevelopedImage image = develop(std::move(result), {}, whitted_scene());
    ASSERT_TRUE(std::holds_alternative<Srgb8Image>(image));
    EXPECT_EQ(std::get<Srgb8Image>(image).bytes, film.bytes);
}

}  // namespace
}  // namespace hikari
