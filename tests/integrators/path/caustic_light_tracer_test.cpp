// The caustic light tracer: the light tracer and the path tracer split the paths between them,
// so the image keeps the plain path tracer's mean (no bias) and stays the same for any thread
// count.
#include "hikari/integrators/path/caustic_light_tracer.h"

#include <string>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "../../io/scene_test_util.h"
#include "hikari/core/color.h"
#include "hikari/integrators/path/path_tracer.h"

namespace hikari {
namespace {

/// A floor and a back wall lit by a small emissive square, a glass ball focusing it onto the
/// floor and a mirror ball throwing it onto the wall: caustics a path tracer meets as fireflies.
const std::string k_caustic_scene = R"({
  "camera": {"eye": [0, 1.2, 4.5], "look_at": [0, 0.7, 0], "fov_y": 45, "width": 32, "height": 24},
  "materials": {"white": {"kd": 0.7}, "glass": {"transparency": 1, "ior": 1.5},
                "mirror": {"reflectivity": 0.95}, "light": {"kd": 0, "emission": 20}},
  "objects": [
    {"type": "triangle", "material": "white", "vertices": [[-3, 0, 3], [3, 0, 3], [3, 0, -2]]},
    {"type": "triangle", "material": "white", "vertices": [[-3, 0, 3], [3, 0, -2], [-3, 0, -2]]},
    {"type": "triangle", "material": "white", "vertices": [[-3, 0, -2], [3, 0, -2], [3, 3, -2]]},
    {"type": "triangle", "material": "white", "vertices": [[-3, 0, -2], [3, 3, -2], [-3, 3, -2]]},
    {"type": "triangle", "material": "light", "vertices": [[-0.3, 2.5, -0.3], [0.3, 2.5, 0.3], [0.3, 2.5, -0.3]]},
    {"type": "triangle", "material": "light", "vertices": [[-0.3, 2.5, -0.3], [-0.3, 2.5, 0.3], [0.3, 2.5, 0.3]]},
    {"type": "sphere", "center": [-0.6, 0.5, 0.3], "radius": 0.5, "material": "glass"},
    {"type": "sphere", "center": [0.8, 0.6, -0.6], "radius": 0.6, "material": "mirror"}]})";

Image render(const Scene& scene, int spp, bool light_traced) {
    PathSettings path;
    path.samples_per_pixel = spp;
    path.light_traced_caustics = light_traced;
    RenderSettings settings;
    settings.aov_buffers = false;
    return render_path(scene, Film(scene.camera, FilmFormat::linear), settings, path).film.linear();
}

/// The mean luminance of rows [y0, y1) of `image`.
double mean_luminance(const Image& image, int y0, int y1) {
    double sum = 0.0;
    for (int y = y0; y < y1; ++y)
        for (int x = 0; x < image.width; ++x)
            sum += luminance(image.pixels[static_cast<size_t>(y) * image.width + x]);
    return sum / ((y1 - y0) * image.width);
}

TEST(CausticLightTracer, KeepsThePathTracersMean) {
    const Scene scene = testing::parse(k_caustic_scene);
    ASSERT_TRUE(traces_caustics_from_lights(scene));
    const Image light = render(scene, 256, true), path = render(scene, 256, false);
    // The whole image, the wall (top half) and the floor with the glass ball's caustic.
    for (const auto& [y0, y1] : {std::pair{0, 24}, std::pair{0, 12}, std::pair{12, 24}}) {
        const double a = mean_luminance(light, y0, y1), b = mean_luminance(path, y0, y1);
        EXPECT_NEAR(a, b, 0.04 * b) << "rows " << y0 << " to " << y1;
    }
}

TEST(CausticLightTracer, ImagesDoNotDependOnTheThreadCount) {
    const Scene scene = testing::parse(k_caustic_scene);
    Image one, two;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = render(scene, 8, true);
    }
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        two = render(scene, 8, true);
    }
    for (size_t i = 0; i < one.pixels.size(); ++i) ASSERT_EQ(one.pixels[i], two.pixels[i]) << i;
}

TEST(CausticLightTracer, OnlyWhereThereAreCausticsToTrace) {
    Scene scene = testing::parse(k_caustic_scene);
    scene.camera.projection = Projection::orthographic;
    EXPECT_FALSE(traces_caustics_from_lights(scene));
    scene = testing::parse(k_caustic_scene);
    for (Material& m : scene.materials) m.reflectivity = m.transparency = 0.0f;
    EXPECT_FALSE(traces_caustics_from_lights(scene));
}

}  // namespace
}  // namespace hikari
