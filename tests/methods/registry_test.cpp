// Every hidden-surface method against ray casting (ARCHITECTURE.md, principle 3): where
// visibility is well defined, all methods see the same primitive at each pixel centre.

#include "hikari/methods/registry.h"

#include <cstdio>
#include <optional>
#include <random>
#include <regex>
#include <string>
#include <string_view>
#include <tuple>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "../io/scene_test_util.h"
#include "../raster/raster_test_util.h"
#include "hikari/core/color.h"
#include "hikari/core/srgb8_encoder.h"
#include "hikari/frame/depth_cue.h"
#include "hikari/io/images/svg_write.h"
#include "hikari/io/scene/scene_json.h"
#include "hikari/raster/lines/line_raster.h"

namespace hikari {
namespace {

/// Method settings for quick tests: the raster methods' shadow maps at 256 texels a side
/// rather than 2048 (the shadows are not what these tests look at).
MethodSettings quick() {
    MethodSettings own;
    own.raster.shadow_map_size = 256;
    return own;
}

/// The methods that must agree with ray casting (the naive depth sort is meant to fail).
const char* const k_correct_methods[] = {"zbuffer", "scanline", "depthsort"};

using testing::scene_file;

/// A soup of random, mutually piercing triangles in front of the camera.
/// `spread` is the half-size of each triangle; with large spreads triangles reach behind the eye
/// and are clipped at the near plane.
Scene random_triangles(unsigned seed, int count, float spread = 1.2f) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> xy(-2.5f, 2.5f), z(-9.0f, -4.0f), jitter(-spread, spread);
    std::string objects;
    for (int i = 0; i < count; ++i) {
        const float cx = xy(rng), cy = xy(rng), cz = z(rng);
        std::string vertices;
        for (int k = 0; k < 3; ++k)
            vertices += fmt::format("{}[{}, {}, {}]", k ? ", " : "", cx + jitter(rng),
                                    cy + jitter(rng), cz + 2 * jitter(rng));
        objects += fmt::format("{}{{\"type\": \"triangle\", \"vertices\": [{}]}}", i ? ", " : "",
                               vertices);
    }
    const std::string json = fmt::format(
        R"({{"camera": {{"fov_y": 60, "width": 256, "height": 256}}, "ambient": 1,
            "objects": [{}]}})",
        objects);
    std::vector<std::string> warnings;
    return parse_scene(json, "random.json", ".", warnings);
}

/// Fraction of pixels whose primitive id equals ray casting's.
double agreement(const Scene& scene, const char* method) {
    const Framebuffer reference =
        find_method("raytrace")->render(scene, Film(scene.camera), {}, MethodSettings{});
    const Framebuffer fb = find_method(method)->render(scene, Film(scene.camera), {}, quick());
    size_t same = 0;
    for (size_t i = 0; i < fb.id.size(); ++i) same += fb.id[i] == reference.id[i];
    return static_cast<double>(same) / static_cast<double>(fb.id.size());
}

TEST(Methods, EveryMethodIsRegistered) {
    for (const char* name : {"raytrace", "zbuffer", "scanline", "depthsort", "depthsort-naive",
                             "wireframe", "hiddenline"})
        EXPECT_NE(find_method(name), nullptr) << name;
    // Only the line methods draw segments (for SVG output).
    for (const Method& m : methods())
        EXPECT_EQ(m.draw != nullptr, m.name == "wireframe" || m.name == "hiddenline") << m.name;
    EXPECT_EQ(methods().front().name, "raytrace");
}

/// The flags of the options `method` declares, in order.
std::vector<std::string> option_flags(const Method& method) {
    std::vector<std::string> flags;
    for (const MethodOption& option : method.options) flags.emplace_back(option.flag);
    return flags;
}

TEST(Methods, EveryMethodDeclaresItsOptions) {
    const std::vector<std::string> ray = {"--spp", "--max-depth", "--shadows", "--light-samples",
                                          "--device"};
    const std::vector<std::string> raster = {"--spp",     "--interp",          "--cull",
                                             "--shadows", "--shadow-map-size", "--light-samples"};
    EXPECT_EQ(option_flags(*find_method("raytrace")), ray);
    std::vector<std::string> zbuffer = raster;
    zbuffer.emplace_back("--device");  // the GPU path's method choice (docs/gpu.md)
    EXPECT_EQ(option_flags(*find_method("zbuffer")), zbuffer);
    for (const char* name : {"scanline", "depthsort-naive"})
        EXPECT_EQ(option_flags(*find_method(name)), raster) << name;
    std::vector<std::string> depth_sort = raster;
    depth_sort.emplace_back("--paint-steps");  // Fig 4.6 part-way
    EXPECT_EQ(option_flags(*find_method("depthsort")), depth_sort);
    const std::vector<std::string> lines = {"--line-width", "--line-color", "--cull"};
    for (const char* name : {"wireframe", "hiddenline"})
        EXPECT_EQ(option_flags(*find_method(name)), lines) << name;
    for (const Method& m : methods()) {
        EXPECT_FALSE(m.options.empty()) << m.name;
        for (const MethodOption& option : m.options) {
            EXPECT_TRUE(takes_option(m, option.flag));
            EXPECT_FALSE(option.help.empty()) << option.flag;
        }
    }
    EXPECT_FALSE(takes_option(*find_method("raytrace"), "--interp"));
    EXPECT_FALSE(takes_option(*find_method("zbuffer"), "--max-depth"));
    // Each option once, whichever methods share it.
    std::vector<std::string> all;
    for (const MethodOption* option : method_options()) all.emplace_back(option->flag);
    EXPECT_EQ(all, (std::vector<std::string>{"--spp", "--max-depth", "--shadows", "--light-samples",
                                             "--device", "--clamp", "--caustics", "--time-limit",
                                             "--progressive", "--filter", "--filter-width",
                                             "--interp", "--cull", "--shadow-map-size",
                                             "--paint-steps", "--line-width", "--line-color"}));
    EXPECT_TRUE(takes_option(*find_method("path"), "--spp"));
    EXPECT_FALSE(takes_option(*find_method("path"), "--shadows"));
}

TEST(Methods, EveryMethodNamesItsShadowModesDefaultFirst) {
    EXPECT_EQ(shadow_mode_list(*find_method("raytrace")), "ray, analytic, none");
    for (const char* name : {"zbuffer", "scanline", "depthsort", "depthsort-naive"}) {
        EXPECT_EQ(shadow_mode_list(*find_method(name)), "map, volume, pcf, pcss, analytic, none")
            << name;
        EXPECT_TRUE(does_shadows(*find_method(name), ShadowMode::volume));
        EXPECT_FALSE(does_shadows(*find_method(name), ShadowMode::ray));
    }
    EXPECT_TRUE(find_method("wireframe")->shadow_modes.empty());
}

TEST(Methods, ShadowsNoneMatchesAMethodWithoutShadowRays) {
    // A sphere over a plane: with --shadows none the ray tracer's picture is the shadowless
    // one, which every raster method draws with --shadows none too.
    const Scene scene = testing::raster_scene_from(R"({
      "camera": {"eye": [0, 2, 4], "look_at": [0, 0.5, 0], "width": 48, "height": 32},
      "ambient": [0.1, 0.1, 0.1], "materials": {"m": {"ka": [1, 1, 1], "kd": [0.8, 0.8, 0.8]}},
      "lights": [{"type": "point", "position": [0, 5, 0], "intensity": [20, 20, 20]}],
      "objects": [{"type": "sphere", "center": [0, 1, 0], "radius": 0.5, "material": "m"},
                  {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "m"}]})");
    MethodSettings own;
    const Framebuffer lit = find_method("raytrace")->render(scene, Film(scene.camera), {}, own);
    own.shadows = ShadowMode::none;
    const Framebuffer none = find_method("raytrace")->render(scene, Film(scene.camera), {}, own);
    const Framebuffer raster = find_method("zbuffer")->render(scene, Film(scene.camera), {}, own);
    // Under the sphere the plane is dark with shadow rays, lit without them, and lit alike by
    // the shadowless raster render.
    int shadowed = 0;
    for (size_t i = 0; i < none.film.linear().pixels.size(); ++i) {
        const float unshadowed = none.film.linear().pixels[i].x;
        if (lit.film.linear().pixels[i].x > 0.5f * unshadowed) continue;
        ++shadowed;
        EXPECT_NEAR(raster.film.linear().pixels[i].x, unshadowed, 0.02f) << i;
    }
    EXPECT_GT(shadowed, 20);
}

/// The method option called `flag`; fails the test when there is none.
const MethodOption& option_named(std::string_view flag) {
    for (const MethodOption* option : method_options())
        if (option->flag == flag) return *option;
    ADD_FAILURE() << "no option " << flag;
    return *method_options().front();
}

TEST(Methods, OptionsSetTheirMethodsSettings) {
    MethodSettings own;
    std::get<OptionalIntegerOption>(option_named("--spp").value).field(own) = 9;
    std::get<OptionalIntegerOption>(option_named("--max-depth").value).field(own) = 2;
    std::get<ChoiceOption<Interpolation>>(option_named("--interp").value).field(own) =
        Interpolation::gouraud;
    std::get<ChoiceOption<bool>>(option_named("--cull").value).field(own) = true;
    std::get<RealOption>(option_named("--line-width").value).field(own) = 2.5f;
    std::get<ColorOption>(option_named("--line-color").value).field(own) = Vec3(1, 0, 0);
    EXPECT_EQ(own.lines.width, 2.5f);
    EXPECT_EQ(own.lines.color, Vec3(1, 0, 0));
    EXPECT_EQ(own.samples_per_pixel, 9);
    EXPECT_EQ(own.max_depth, 2);
    EXPECT_EQ(own.raster.interp, Interpolation::gouraud);
    EXPECT_TRUE(own.raster.cull_back_faces);
}

TEST(Methods, ChoiceTablesNameEveryValueOnce) {
    for (const Choice<Interpolation>& c : k_interpolation_choices) {
        EXPECT_EQ(choice_value<Interpolation>(k_interpolation_choices, c.name), c.value);
        EXPECT_EQ(choice_name<Interpolation>(k_interpolation_choices, c.value), c.name);
    }
    for (const Choice<bool>& c : k_cull_choices)
        EXPECT_EQ(choice_value<bool>(k_cull_choices, c.name), c.value);
    EXPECT_EQ(choice_value<Interpolation>(k_interpolation_choices, "smooth"), std::nullopt);
    // The defaults have names (--help shows them).
    EXPECT_EQ(choice_name<Interpolation>(k_interpolation_choices, RasterSettings{}.interp),
              "phong");
    EXPECT_EQ(choice_name<bool>(k_cull_choices, RasterSettings{}.cull_back_faces), "none");
}

TEST(Methods, EveryMethodFillsAnEightBitFilmWithItsLinearFilmEncoded) {
    // The assignment shows background around its sphere (raster methods write it too).
    for (const char* name : {"assignment.json", "whitted.json"}) {
        const Scene scene = scene_file(name, 48, 32);
        for (const Method& m : methods()) {
            RenderSettings colour_only;
            colour_only.aov_buffers = false;
            const Framebuffer linear = m.render(scene, Film(scene.camera), colour_only, quick());
            const Framebuffer srgb8 =
                m.render(scene, Film(scene.camera, FilmFormat::srgb8), colour_only, quick());
            EXPECT_EQ(srgb8.film.srgb8().bytes, encode_srgb8(linear.film.linear()).bytes)
                << name << ", " << m.name;
        }
    }
}

TEST(Methods, RenderSceneDepthCuesEveryMethod) {
    // render_scene applies the scene's depth cue to any method, on a linear film with the depth
    // AOV even when an 8-bit film without AOVs was asked for.
    Scene scene = scene_file("whitted.json", 48, 32);
    DepthCue cue;
    cue.near = 4.0f;
    cue.far = 14.0f;
    cue.color = Vec3(0.5f, 0.25f, 0.0f);
    for (const Method& m : methods()) {
        SCOPED_TRACE(m.name);
        scene.depth_cue.reset();
        const Framebuffer plain = render_scene(m, scene, Film(scene.camera), {}, quick());
        scene.depth_cue = cue;
        RenderSettings colour_only;
        colour_only.aov_buffers = false;
        const Framebuffer cued =
            render_scene(m, scene, Film(scene.camera, FilmFormat::srgb8), colour_only, quick());
        ASSERT_EQ(cued.film.format(), FilmFormat::linear);
        ASSERT_EQ(cued.depth.size(), plain.depth.size());
        for (size_t i = 0; i < plain.depth.size(); ++i) {
            const float w = depth_cue_weight(cue, plain.depth[i]);
            const Vec3 want = w * plain.film.linear().pixels[i] + (1.0f - w) * *cue.color;
            for (int a = 0; a < 3; ++a)
                ASSERT_NEAR(cued.film.linear().pixels[i][a], want[a], 1e-6f) << "pixel " << i;
        }
    }
}

/// The drawing an SVG document of svg_document's form shows: its background and lines, read
/// back from the text (8-bit sRGB colours decoded).
LineDrawing drawing_from_svg(const std::string& svg, int width, int height, float line_width) {
    auto colour = [](const std::string& hex) {
        const auto channel = [&](int k) {
            return srgb_to_linear(float(std::stoi(hex.substr(1 + 2 * k, 2), nullptr, 16)) / 255);
        };
        return Vec3(channel(0), channel(1), channel(2));
    };
    LineDrawing d;
    d.width = width;
    d.height = height;
    d.line_width = line_width;
    std::smatch m;
    EXPECT_TRUE(std::regex_search(svg, m, std::regex(R"re(<rect [^>]*fill="(#[0-9a-f]{6})")re")));
    d.background = colour(m[1]);
    const std::regex line(
        R"re(<line x1="([-0-9.]+)" y1="([-0-9.]+)" x2="([-0-9.]+)" y2="([-0-9.]+)" stroke="(#[0-9a-f]{6})"/>)re");
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), line); it != std::sregex_iterator();
         ++it) {
        LineSegment s;
        s.a = {std::stof((*it)[1]), std::stof((*it)[2])};
        s.b = {std::stof((*it)[3]), std::stof((*it)[4])};
        s.color = colour((*it)[5]);
        d.segments.push_back(s);
    }
    return d;
}

TEST(Methods, LineMethodsSvgShowsTheirImage) {
    // The SVG's lines, rasterized again, give the method's own image (some 58 dB). With a depth
    // cue, the image is cued pixel by pixel, at the depth of the line covering most of it, and
    // the SVG line by line: they differ where lines at different depths share a pixel or cover
    // part of one (some 32 dB for the wireframe, whose front and back lines cross everywhere).
    Scene scene = scene_file("teapot.json", 96, 72);
    DepthCue cue;
    cue.near = 3.0f;
    cue.far = 6.0f;
    MethodSettings own;
    own.lines.width = 1.5f;
    for (const auto& [name, cued, min_psnr] :
         {std::tuple{"wireframe", false, 50.0}, std::tuple{"hiddenline", false, 50.0},
          std::tuple{"wireframe", true, 30.0}, std::tuple{"hiddenline", true, 30.0}}) {
        SCOPED_TRACE(std::string(name) + (cued ? ", cued" : ""));
        scene.depth_cue.reset();
        if (cued) scene.depth_cue = cue;
        const Method& m = *find_method(name);
        const Framebuffer image = render_scene(m, scene, Film(scene.camera), {}, own);
        const LineDrawing read = drawing_from_svg(svg_document(draw_scene(m, scene, own)),
                                                  scene.camera.width, scene.camera.height, 1.5f);
        EXPECT_GT(read.segments.size(), 100u);
        const Framebuffer again = rasterize_lines(read, Film(scene.camera), false);
        double sum = 0;
        for (size_t i = 0; i < image.film.linear().pixels.size(); ++i)
            for (int a = 0; a < 3; ++a) {
                const double d =
                    linear_to_srgb(std::clamp(image.film.linear().pixels[i][a], 0.0f, 1.0f)) -
                    linear_to_srgb(std::clamp(again.film.linear().pixels[i][a], 0.0f, 1.0f));
                sum += d * d;
            }
        const double mse = sum / (3.0 * double(image.film.linear().pixels.size()));
        EXPECT_GT(10 * std::log10(1 / mse), min_psnr) << "PSNR in sRGB";
    }
}

TEST(Methods, AgreeWithRayCastingOnRandomPiercingTriangles) {
    for (unsigned seed : {1u, 2u}) {
        const Scene scene = random_triangles(seed, 60);
        for (const char* m : k_correct_methods)
            EXPECT_GE(agreement(scene, m), 0.998) << m << ", seed " << seed;
    }
}

TEST(Methods, AgreeWithRayCastingOnDenseSoupsCrossingTheNearPlane) {
    // Large triangles: many cycles to cut in the depth sort, and far/near ratios that would
    // ruin an NDC depth key.
    const Scene scene = random_triangles(7, 200, 2.5f);
    for (const char* m : k_correct_methods) EXPECT_GE(agreement(scene, m), 0.998) << m;
}

TEST(Methods, AgreeWithRayCastingOnCyclicOverlap) {
    const Scene scene = scene_file("depth-sort-cyclic.json", 256, 256);  // Fig 4.9a
    for (const char* m : k_correct_methods) EXPECT_GE(agreement(scene, m), 0.998) << m;
}

TEST(Methods, AgreeWithRayCastingOnPiercingPair) {
    const Scene scene = scene_file("depth-sort-piercing.json", 256, 256);  // Fig 4.9b
    for (const char* m : k_correct_methods) EXPECT_GE(agreement(scene, m), 0.998) << m;
}

TEST(Methods, AgreeWithRayCastingOnTheBunny) {
    const Scene scene = scene_file("bunny.json", 160, 120);
    for (const char* m : k_correct_methods) EXPECT_GE(agreement(scene, m), 0.998) << m;
}

TEST(Methods, NaiveDepthSortFailsWhereTheLectureSaysItDoes) {
    // Fig 4.7, 4.9a and 4.9b: whole-polygon ordering by centroid gets these visibly wrong.
    for (const char* name :
         {"depth-sort-centroid.json", "depth-sort-cyclic.json", "depth-sort-piercing.json"}) {
        const Scene scene = scene_file(name, 256, 256);
        EXPECT_LT(agreement(scene, "depthsort-naive"), 0.995) << name;
        EXPECT_GE(agreement(scene, "depthsort"), 0.998) << name;
    }
}

}  // namespace
}  // namespace hikari

namespace hikari {
namespace {

using testing::psnr;
using testing::scene_file;

// Issue 28: --spp anti-aliases the raster methods by supersampling at the ray tracer's own
// sub-pixel points, so at equal spp the two agree edge pixel for edge pixel.
TEST(Methods, RasterSupersamplingMatchesTheRayTracersSamples) {
    Scene scene = scene_file("assignment.json", 48, 40);
    scene.lights.resize(1);  // no shadows to differ by maps and rays
    MethodSettings one, many;
    many.samples_per_pixel = 16;
    one.shadows = many.shadows = ShadowMode::none;
    const Framebuffer ray =
        render_scene(*find_method("raytrace"), scene, Film(scene.camera), {}, many);
    for (const char* name : {"zbuffer", "scanline", "depthsort"}) {
        SCOPED_TRACE(name);
        const Method& m = *find_method(name);
        const Framebuffer aliased = render_scene(m, scene, Film(scene.camera), {}, one);
        const Framebuffer smooth = render_scene(m, scene, Film(scene.camera), {}, many);
        // Edge pixels take values between the sphere's and the background's.
        int fractional = 0;
        const Vec3 background = scene.background;
        for (size_t i = 0; i < smooth.film.linear().pixels.size(); ++i) {
            const Vec3 a = aliased.film.linear().pixels[i], s = smooth.film.linear().pixels[i];
            if (a == background && s != background) ++fractional;
        }
        EXPECT_GT(fractional, 20);
        EXPECT_GT(psnr(smooth, ray), 35.0);
        EXPECT_GT(psnr(smooth, ray), psnr(aliased, ray));
        // The AOVs stay the pixel centres'.
        EXPECT_EQ(smooth.id, aliased.id);
        EXPECT_EQ(smooth.depth, aliased.depth);
    }
}

// Issue 28: a floor under a camera 0.001 above it is drawn to the bottom row by every raster
// method, with or without an unrelated far plane, at any field of view: the near plane comes
// from the geometry in front of the eye, not from the far plane.
TEST(Methods, LowCameraKeepsTheFloorInEveryRasterMethod) {
    for (const bool far_wall : {false, true})
        for (const float fov : {60.0f, 120.0f, 179.0f})
            for (const bool sphere : {false, true}) {
                SCOPED_TRACE(fmt::format("far wall {}, fov {}, sphere {}", far_wall, fov, sphere));
                std::string objects =
                    R"({"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "m"})";
                if (far_wall)
                    objects +=
                        R"(, {"type": "plane", "point": [0, 0, -50], "normal": [0, 0, 1], "material": "m"})";
                if (sphere)
                    objects +=
                        R"(, {"type": "sphere", "center": [1, 0.5, -4], "radius": 0.5, "material": "m"})";
                const Scene scene = testing::parse(fmt::format(
                    R"({{"camera": {{"eye": [0, 0.001, 0], "look_at": [0.2, 0.0005, -1], "fov_y": {},
                          "width": 48, "height": 36}},
                        "materials": {{"m": {{"kd": 0.5}}}}, "objects": [{}]}})",
                    fov, objects));
                const Framebuffer ray =
                    render_scene(*find_method("raytrace"), scene, Film(scene.camera), {}, {});
                for (const char* name : {"zbuffer", "scanline", "depthsort"}) {
                    SCOPED_TRACE(name);
                    MethodSettings own;
                    own.shadows = ShadowMode::none;
                    const Framebuffer raster =
                        render_scene(*find_method(name), scene, Film(scene.camera), {}, own);
                    EXPECT_GT(testing::id_agreement(raster, ray), 0.995);
                    // The bottom row is all floor (primitive 0).
                    const size_t last = raster.id.size() - scene.camera.width;
                    for (int x = 0; x < scene.camera.width; ++x)
                        ASSERT_EQ(raster.id[last + x], 1U) << "pixel " << x;
                }
            }
}

}  // namespace
}  // namespace hikari
