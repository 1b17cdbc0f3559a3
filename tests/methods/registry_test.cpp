// Every hidden-surface method against ray casting (ARCHITECTURE.md, principle 3): where
// visibility is well defined, all methods see the same primitive at each pixel centre.

#include "hikari/methods/registry.h"

#include <random>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "hikari/io/scene_json.h"

namespace hikari {
namespace {

/// The methods that must agree with ray casting (the naive depth sort is meant to fail).
const char* const k_correct_methods[] = {"zbuffer", "scanline", "depthsort"};

Scene scene_file(const std::string& name, int width, int height) {
    std::vector<std::string> warnings;
    Scene s = load_scene_file(std::string(HIKARI_SOURCE_DIR) + "/scenes/" + name, warnings);
    s.camera.width = width;
    s.camera.height = height;
    return s;
}

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
    const Framebuffer fb =
        find_method(method)->render(scene, Film(scene.camera), {}, MethodSettings{});
    size_t same = 0;
    for (size_t i = 0; i < fb.id.size(); ++i) same += fb.id[i] == reference.id[i];
    return static_cast<double>(same) / static_cast<double>(fb.id.size());
}

TEST(Methods, EveryMethodIsRegistered) {
    for (const char* name : {"raytrace", "zbuffer", "scanline", "depthsort", "depthsort-naive"})
        EXPECT_NE(find_method(name), nullptr) << name;
    EXPECT_EQ(methods().front().name, "raytrace");
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
