// --aov ambient | diffuse | specular: each term of Fig 4.29 alone, and the three add up to the
// colour image in every method that shades by them.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "../io/scene_test_util.h"
#include "hikari/methods/registry.h"
#include "hikari/shading/shading_terms.h"

namespace hikari {
namespace {

// Spheres, a plane and a triangle under a point light, a directional light and ambient light,
// with a sky the colour image shows and a mirror sphere that reflects all of it.
const std::string k_lit_spheres_template = R"({
  "camera": {"eye": [0, 1.5, 5], "look_at": [0, 0.5, 0], "fov_y": 45, "width": 48, "height": 36},
  "background": [0.2, 0.3, 0.5],
  "ambient": [0.3, 0.3, 0.3],
  "materials": {
    "red": {"ka": [0.3, 0.05, 0.05], "kd": [0.7, 0.1, 0.1], "ks": [0.5, 0.5, 0.5], "shininess": 20},
    "floor": {"ka": [0.2, 0.2, 0.2], "kd": [0.6, 0.6, 0.5], "ks": [0.1, 0.1, 0.1], "shininess": 5},
    "mirror": {"ka": [0.05, 0.05, 0.05], "kd": [0.1, 0.1, 0.1], "ks": [0.8, 0.8, 0.8],
               "shininess": 80, "reflectivity": 0.6}
  },
  "lights": [
    {"type": "point", "position": [3, 5, 4], "intensity": [40, 40, 40]},
    {"type": "directional", "direction": [-1, -2, -1], "intensity": [0.4, 0.4, 0.3]}
  ],
  "objects": [
    {"type": "sphere", "center": [-0.8, 0.7, 0], "radius": 0.7, "material": "red"},
    {"type": "sphere", "center": [0.9, 0.6, -0.5], "radius": 0.6, "material": "MIRROR_OR_RED"},
    {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
    {"type": "triangle", "vertices": [[-2, 0.01, -2], [-0.5, 1.5, -2.5], [0.5, 0.01, -2]],
     "material": "red"}
  ]
})";

Image render_linear(const Method& method, const Scene& scene) {
    RenderSettings settings;
    settings.aov_buffers = false;
    MethodSettings own;
    own.raster.shadow_map_size = 256;  // shadow-mapped, but quickly
    Framebuffer fb =
        render_scene(method, scene, Film(scene.camera, FilmFormat::linear), settings, own);
    return aov_image(std::move(fb), Aov::color);
}

/// The largest |ambient + diffuse + specular − colour| over the image.
float term_sum_error(const std::string& method_name, const std::string& json) {
    const Scene scene = testing::parse(json);
    const Method& method = *find_method(method_name);
    const Image colour = render_linear(method, scene);
    const Image a = render_linear(method, isolate_shading_term(scene, ShadingTerm::ambient));
    const Image d = render_linear(method, isolate_shading_term(scene, ShadingTerm::diffuse));
    const Image s = render_linear(method, isolate_shading_term(scene, ShadingTerm::specular));
    float worst = 0.0f;
    for (size_t i = 0; i < colour.pixels.size(); ++i) {
        const Vec3 sum = a.pixels[i] + d.pixels[i] + s.pixels[i];
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(sum[c] - colour.pixels[i][c]));
    }
    return worst;
}

std::string with_second_sphere(const std::string& material) {
    std::string json = k_lit_spheres_template;
    json.replace(json.find("MIRROR_OR_RED"), 13, material);
    return json;
}

TEST(ShadingTerms, TheThreeTermsSumToTheColourInEveryShadingMethod) {
    for (const char* method : {"raytrace", "zbuffer", "scanline", "depthsort"})
        EXPECT_LT(term_sum_error(method, with_second_sphere("red")), 1e-5f) << method;
}

TEST(ShadingTerms, MirrorsReflectEachTermSeparately) {
    // Whitted's colour is linear in the terms: the mirror's reflection of each term is that
    // term's, so the sum still holds.
    EXPECT_LT(term_sum_error("raytrace", with_second_sphere("mirror")), 1e-5f);
}

TEST(ShadingTerms, EachTermHoldsOnlyItsOwnLight) {
    const Scene scene = testing::parse(with_second_sphere("red"));
    const Method& raytrace = *find_method("raytrace");
    const Image a = render_linear(raytrace, isolate_shading_term(scene, ShadingTerm::ambient));
    const Image d = render_linear(raytrace, isolate_shading_term(scene, ShadingTerm::diffuse));
    const Image s = render_linear(raytrace, isolate_shading_term(scene, ShadingTerm::specular));
    // Top-left corner: sky. The ambient image keeps the background, the others are black there.
    EXPECT_EQ(a.at(0, 0), Vec3(0.2f, 0.3f, 0.5f));
    EXPECT_EQ(d.at(0, 0), Vec3(0.0f));
    EXPECT_EQ(s.at(0, 0), Vec3(0.0f));
    // The ambient term on a lit surface is ka·Ia, flat: the same at every pixel of the floor.
    const Vec3 floor_ambient = Vec3(0.2f) * Vec3(0.3f);
    EXPECT_NEAR(a.at(2, 35).x, floor_ambient.x, 1e-6f);
    // Diffuse light varies and specular highlights exist somewhere.
    float brightest_specular = 0.0f;
    for (const Vec3& p : s.pixels) brightest_specular = std::max(brightest_specular, p.x);
    EXPECT_GT(brightest_specular, 0.1f);
    EXPECT_GT(d.at(2, 35).x, 0.0f);
}

TEST(ShadingTerms, TermsAreSetOnTheMaterialsAndBackground) {
    const Scene scene = testing::parse(with_second_sphere("red"));
    const Scene diffuse = isolate_shading_term(scene, ShadingTerm::diffuse);
    for (const Material& m : diffuse.materials) {
        EXPECT_EQ(m.ka, Vec3(0.0f));
        EXPECT_EQ(m.ks, Vec3(0.0f));
    }
    EXPECT_EQ(diffuse.materials[0].kd, scene.materials[0].kd);
    EXPECT_FALSE(diffuse.show_background);
    EXPECT_TRUE(isolate_shading_term(scene, ShadingTerm::ambient).show_background);
}

}  // namespace
}  // namespace hikari
