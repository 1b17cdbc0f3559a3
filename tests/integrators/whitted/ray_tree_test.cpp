// whitted_ray_tree: the tree the tracer records for one pixel sums to the pixel the render gives.

#include <string>

#include <gtest/gtest.h>

#include "../../io/scene_test_util.h"
#include "hikari/integrators/whitted/whitted.h"

namespace hikari {
namespace {

const std::string k_glass_and_mirror_spheres = R"({
  "camera": {"eye": [0, 1, 6], "look_at": [0, 0.6, 0], "fov_y": 40, "width": 40, "height": 30},
  "background": [0.4, 0.5, 0.8],
  "ambient": 0.1,
  "materials": {
    "floor": {"kd": [0.6, 0.6, 0.5], "ka": 0.2},
    "glass": {"ks": 0.5, "shininess": 60, "reflectivity": 0.1, "transparency": 0.9, "ior": 1.5},
    "mirror": {"kd": 0.1, "reflectivity": 0.8}
  },
  "lights": [{"type": "point", "position": [3, 5, 4], "intensity": 40},
             {"type": "directional", "direction": [0, -1, -0.3], "intensity": 0.3}],
  "objects": [
    {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
    {"type": "sphere", "center": [-0.8, 0.7, 0], "radius": 0.7, "material": "glass"},
    {"type": "sphere", "center": [0.9, 0.6, -0.8], "radius": 0.6, "material": "mirror"}
  ]
})";

TEST(RayTree, TheTreeSumsToTheRenderedPixel) {
    const Scene scene = testing::parse(k_glass_and_mirror_spheres);
    RenderSettings settings;
    settings.aov_buffers = false;
    const Framebuffer fb = render_whitted(scene, Film(scene.camera, FilmFormat::linear), settings);
    for (const auto& [x, y] :
         {std::pair{14, 15}, std::pair{26, 14}, std::pair{5, 25}, std::pair{20, 2}}) {
        const std::vector<RayTreeNode> tree = whitted_ray_tree(scene, WhittedSettings{}, x, y);
        ASSERT_FALSE(tree.empty());
        EXPECT_EQ(tree.front().total, fb.film.linear().at(x, y)) << x << "," << y;
        // Every node returns local + Σ weight × child total, as the recursion adds them.
        for (size_t n = 0; n < tree.size(); ++n) {
            Vec3 sum = tree[n].local;
            for (const RayTreeNode& c : tree)
                if (c.parent == static_cast<int>(n)) sum += c.weight * c.total;
            EXPECT_NEAR(sum.x, tree[n].total.x, 1e-5f);
            EXPECT_LE(tree[n].depth, WhittedSettings{}.max_depth - 1);
        }
    }
}

TEST(RayTree, GlassSpawnsMirrorAndRefractedRaysAndShadowRaysAreListed) {
    const Scene scene = testing::parse(k_glass_and_mirror_spheres);
    const std::vector<RayTreeNode> tree = whitted_ray_tree(scene, WhittedSettings{}, 14, 15);
    ASSERT_TRUE(tree.front().hit);
    EXPECT_EQ(tree.front().surface.id, 1u);  // the glass sphere
    int mirror = 0, refracted = 0;
    for (const RayTreeNode& n : tree) {
        mirror += n.parent == 0 && n.kind == RayTreeNode::Kind::mirror;
        refracted += n.parent == 0 && n.kind == RayTreeNode::Kind::refracted;
    }
    EXPECT_EQ(mirror, 1);
    EXPECT_EQ(refracted, 1);
    EXPECT_EQ(tree.front().shadow_rays.size(), 2u);
}

}  // namespace
}  // namespace hikari
