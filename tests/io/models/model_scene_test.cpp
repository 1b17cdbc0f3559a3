#include "hikari/io/models/model_scene.h"

#include <gtest/gtest.h>

#include <fstream>

#include "../temp_dir.h"
#include "hikari/scene/camera.h"

namespace hikari {
namespace {

/// A long, off-centre box: framing must find it wherever it is.
MeshData box(Vec3 lo, Vec3 hi) {
    PolygonMesh m;
    m.positions = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                   {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    m.add_face({0, 3, 2, 1});
    m.add_face({4, 5, 6, 7});
    m.add_face({0, 1, 5, 4});
    m.add_face({3, 7, 6, 2});
    m.add_face({0, 4, 7, 3});
    m.add_face({1, 2, 6, 5});
    return build_mesh("box.obj", std::move(m));
}

Vec3 vec3(const nlohmann::json& j) {
    return {j[0].get<float>(), j[1].get<float>(), j[2].get<float>()};
}

TEST(ModelScene, FramingKeepsEveryVertexInViewAndFillsIt) {
    const MeshData mesh = box({100, -3, 40}, {108, 1, 42});
    const nlohmann::json doc = model_scene_document("box.obj", mesh, {});
    Camera c;
    c.eye = vec3(doc["camera"]["eye"]);
    c.look_at = vec3(doc["camera"]["look_at"]);
    c.up = vec3(doc["camera"]["up"]);
    c.fov_y_degrees = doc["camera"]["fov_y"].get<float>();
    c.width = doc["camera"]["width"].get<int>();
    c.height = doc["camera"]["height"].get<int>();
    EXPECT_EQ(c.look_at, (Vec3{104, -1, 41}));  // the box's centre
    const CameraFrame f = make_camera_frame(c);
    float widest = 0, tallest = 0;
    for (const Vec3& p : mesh.positions) {
        const Vec3 d = p - c.eye;
        const float depth = dot(d, f.forward);
        ASSERT_GT(depth, 0.0f);
        // Normalized screen coordinates: ±1 at the image's edges.
        const float x = dot(d, f.right) / depth / (f.tan_half_fov_y * f.aspect);
        const float y = dot(d, f.up) / depth / f.tan_half_fov_y;
        EXPECT_LT(std::abs(x), 1.0f);
        EXPECT_LT(std::abs(y), 1.0f);
        widest = std::max(widest, std::abs(x));
        tallest = std::max(tallest, std::abs(y));
    }
    EXPECT_GT(std::max(widest, tallest), 0.5f);  // not a speck in the middle
    EXPECT_EQ(doc["lights"].size(), 2u);         // the key and the fill
}

TEST(ModelScene, GroundLiesJustUnderTheModel) {
    const MeshData mesh = box({0, 2, 0}, {1, 3, 1});
    const nlohmann::json doc = model_scene_document("box.obj", mesh, {.ground = true, .mesh = {}});
    ASSERT_EQ(doc["objects"].size(), 2u);
    const nlohmann::json& plane = doc["objects"][1];
    EXPECT_EQ(plane["type"], "plane");
    EXPECT_LT(vec3(plane["point"]).y, 2.0f);
    EXPECT_GT(vec3(plane["point"]).y, 1.99f);
}

TEST(ModelScene, FileCameraAndLightsAreUsed) {
    MeshData mesh = box({0, 0, 0}, {1, 1, 1});
    ModelCamera camera;
    camera.camera.eye = {5, 6, 7};
    camera.camera.look_at = {0, 0, 0};
    camera.camera.fov_y_degrees = 25;
    camera.aspect = 2.0f;
    mesh.cameras.push_back(camera);
    mesh.lights.push_back(PointLight{{1, 5, 1}, {10, 10, 10}});
    const nlohmann::json doc = model_scene_document("box.gltf", mesh, {});
    EXPECT_EQ(vec3(doc["camera"]["eye"]), (Vec3{5, 6, 7}));
    EXPECT_EQ(doc["camera"]["fov_y"].get<float>(), 25.0f);
    EXPECT_EQ(doc["camera"]["width"].get<int>(), 2 * doc["camera"]["height"].get<int>());
    EXPECT_TRUE(doc["lights"].empty());  // the file's own light comes with the mesh
}

TEST(ModelScene, LoadsTheModelFileOnceAsAScene) {
    testing::TempDir dir;
    std::ofstream(dir / "tri.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    std::vector<std::string> warnings;
    const Scene scene = load_model_scene(dir / "tri.obj", {.ground = true, .mesh = {}}, warnings);
    EXPECT_EQ(scene.triangles.indices.size(), 1u);
    EXPECT_EQ(scene.planes.size(), 1u);
    EXPECT_EQ(scene.lights.size(), 2u);
    EXPECT_EQ(scene.camera.width, k_model_image_width);
}

}  // namespace
}  // namespace hikari
