#include "hikari/io/scene/scene_json.h"
#include "../scene_test_util.h"

#include <gtest/gtest.h>

#include "../temp_dir.h"
#include "hikari/core/error.h"
#include "hikari/io/images/image_write.h"

namespace hikari {
namespace {

using testing::error_of;
using testing::parse;

TEST(SceneJson, DefaultSceneIsTheAssignment) {
    const Scene s = load_default_scene();
    EXPECT_EQ(s.camera.width, 512);
    EXPECT_EQ(s.camera.height, 512);
    EXPECT_FLOAT_EQ(s.camera.fov_y_degrees, 60);
    ASSERT_EQ(s.spheres.size(), 1u);
    EXPECT_EQ(s.spheres[0].center, Vec3(0, 0, -3));
    ASSERT_EQ(s.lights.size(), 1u);
    const auto& light = std::get<DirectionalLight>(s.lights[0]);
    EXPECT_NEAR(light.direction.x, 1 / std::sqrt(3.0f), 1e-6);
    EXPECT_FLOAT_EQ(s.materials[s.spheres[0].material].shininess, 40);
}

TEST(SceneJson, PrimitiveIdsFollowFileOrder) {
    const Scene s = parse(R"({"objects": [
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0]},
        {"type": "sphere", "center": [0, 0, 0], "radius": 1},
        {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}]})");
    EXPECT_EQ(s.planes[0].id, 0u);
    EXPECT_EQ(s.spheres[0].id, 1u);
    EXPECT_EQ(s.triangles.id[0], 2u);
    EXPECT_EQ(s.primitive_count, 3u);
}

TEST(SceneJson, TriangleNormalFollowsLectureWinding) {
    const Scene s = parse(R"({"objects": [
        {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}]})");
    EXPECT_EQ(s.triangles.normals[0], Vec3(0, 0, 1));
}

TEST(SceneJson, EdgeFlagsFollowTrianglesThroughMirroringTransforms) {
    testing::TempDir dir;
    testing::write_text(dir / "quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
    const std::string mesh = R"({"type": "mesh", "file": ")" + (dir / "quad.obj").string();
    const Scene s =
        parse(R"({"objects": [
        {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]},)" +
              mesh + R"("}, )" + mesh + R"(", "transform": [{"scale": [-1, 1, 1]}]}]})");
    // A triangle object is all edges; the quad's fan (1 2 3), (1 3 4) leaves out 3→1 and 1→3.
    ASSERT_EQ(s.triangles.edge_flags.size(), 5u);
    EXPECT_EQ(s.triangles.edge_flags[0], k_all_edges);
    EXPECT_EQ(s.triangles.edge_flags[1], 0b011);
    EXPECT_EQ(s.triangles.edge_flags[2], 0b110);
    // Mirrored, the corners are swapped to (1 3 2) and (1 4 3): the diagonal 1→3 becomes edge 0
    // of the first and edge 2 (3→1) of the second.
    EXPECT_EQ(s.triangles.edge_flags[3], 0b110);
    EXPECT_EQ(s.triangles.edge_flags[4], 0b011);
    for (size_t t = 3; t < 5; ++t) {
        const auto& idx = s.triangles.indices[t];
        for (int k = 0; k < 3; ++k) {
            const Vec3 d = s.triangles.positions[idx[(k + 1) % 3]] - s.triangles.positions[idx[k]];
            const bool diagonal = d.x != 0 && d.y != 0;
            EXPECT_EQ(((s.triangles.edge_flags[t] >> k) & 1) == 0, diagonal) << t << ", " << k;
        }
    }
}

TEST(SceneJson, TransformStepsApplyInOrder) {
    // scale by 2, then translate by (1, 0, 0): (1, 0, 0) -> (2, 0, 0) -> (3, 0, 0).
    const Scene s = parse(R"({"objects": [
        {"type": "triangle", "vertices": [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
         "transform": [{"scale": [2, 2, 2]}, {"translate": [1, 0, 0]}]}]})");
    EXPECT_EQ(s.triangles.positions[0], Vec3(3, 0, 0));
    EXPECT_EQ(s.triangles.positions[1], Vec3(1, 2, 0));
}

TEST(SceneJson, FarTranslationsAreNotSingular) {
    // The singularity test looks at the linear part: a model moved 1000 units or more loads.
    const Scene s = parse(R"({"objects": [
        {"type": "triangle", "vertices": [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
         "transform": [{"translate": [5000, 0, -20000]}]}]})");
    EXPECT_EQ(s.triangles.positions[0], Vec3(5001, 0, -20000));
    EXPECT_NE(error_of(R"({"objects": [
        {"type": "triangle", "vertices": [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
         "transform": [{"scale": [1, 0, 1]}, {"translate": [5000, 0, 0]}]}]})")
                  .find("the transform is singular"),
              std::string::npos);
}

TEST(SceneJson, SyntaxErrorGivesLineAndColumn) {
    const std::string e = error_of("{\n  \"objects\": [\n    {\"type\": \"sphere\",}\n  ]\n}");
    EXPECT_EQ(e.rfind("s.json:3:", 0), 0u) << e;
}

TEST(SceneJson, WrongValueGivesJsonPath) {
    EXPECT_EQ(error_of(R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": -1}]})"),
              "s.json: objects[0].radius: expected a positive number");
    EXPECT_EQ(error_of(R"({"objects": [{"type": "sphere", "center": [0, 0], "radius": 1}]})"),
              "s.json: objects[0].center: expected an array of 3 numbers, got an array");
    EXPECT_EQ(error_of(R"({"objects": [{"type": "sphere", "center": [0, 0, 0]}]})"),
              "s.json: objects[0].radius: missing (this key is required)");
}

TEST(SceneJson, TriangleUvsAndPlaneUvScale) {
    const Scene s = parse(R"({"objects": [
        {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]},
        {"type": "triangle", "vertices": [[0, 0, 1], [1, 0, 1], [0, 1, 1]],
         "uvs": [[0.5, 0.25], [1, 0], [0, 2]]},
        {"type": "triangle", "vertices": [[0, 0, 2], [1, 0, 2], [0, 1, 2]]},
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "uv_scale": 3},
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0]}]})");
    // One uv per vertex from the first object with any on; (0, 0) for those without.
    ASSERT_EQ(s.triangles.uvs.size(), s.triangles.positions.size());
    const auto uv_of = [&](size_t triangle, int corner) {
        return s.triangles.uvs[s.triangles.indices[triangle][corner]];
    };
    EXPECT_EQ(uv_of(0, 1).x, 0.0f);
    EXPECT_EQ(uv_of(1, 0).x, 0.5f);
    EXPECT_EQ(uv_of(1, 0).y, 0.25f);
    EXPECT_EQ(uv_of(1, 2).y, 2.0f);
    EXPECT_EQ(uv_of(2, 2).y, 0.0f);
    EXPECT_EQ(s.planes[0].uv_scale, 3.0f);
    EXPECT_EQ(s.planes[1].uv_scale, 1.0f);
    // No uvs anywhere: none stored.
    EXPECT_TRUE(parse(R"({"objects": [{"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0],
        [0, 1, 0]]}]})")
                    .triangles.uvs.empty());
}

TEST(SceneJson, MeshUvsKeepOnePerVertex) {
    // A mesh without vt between a triangle and a mesh with them: its vertices get (0, 0) and
    // every later vertex keeps its own.
    testing::TempDir dir;
    const std::string quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
    testing::write_text(dir / "bare.obj", quad + "f 1 2 3 4\n");
    testing::write_text(dir / "uv.obj",
                        quad + "vt 0.5 0.5\nvt 1 0.5\nvt 1 1\nvt 0.5 1\n" + "f 1/1 2/2 3/3 4/4\n");
    const Scene s = parse(R"({"objects": [
        {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]],
         "uvs": [[0.1, 0.2], [0.3, 0.4], [0.5, 0.6]]},
        {"type": "mesh", "file": ")" +
                          (dir / "bare.obj").string() + R"("},
        {"type": "mesh", "file": ")" +
                          (dir / "uv.obj").string() + R"("}]})");
    const TriangleSet& t = s.triangles;
    ASSERT_EQ(t.uvs.size(), t.positions.size());
    EXPECT_EQ(t.uvs[t.indices[0][2]].y, 0.6f);
    for (size_t k = 1; k < 3; ++k)
        for (const uint32_t v : t.indices[k]) EXPECT_EQ(t.uvs[v].x, 0.0f);
    for (size_t k = 3; k < 5; ++k)
        for (const uint32_t v : t.indices[k]) {
            // uv.obj maps its unit quad to [0.5, 1]²: u = 0.5 + x / 2, v = 0.5 + y / 2.
            EXPECT_EQ(t.uvs[v].x, 0.5f + t.positions[v].x / 2);
            EXPECT_EQ(t.uvs[v].y, 0.5f + t.positions[v].y / 2);
        }
}

TEST(SceneJson, SpotLightReadsItsCone) {
    const Scene s = parse(R"({"lights": [{"type": "spot", "position": [1, 4, 1],
        "direction": [0, -2, 0], "intensity": 3, "inner_angle": 20, "outer_angle": 30}],
        "objects": []})");
    ASSERT_EQ(s.lights.size(), 1u);
    const auto& spot = std::get<SpotLight>(s.lights[0]);
    EXPECT_EQ(spot.position, Vec3(1, 4, 1));
    EXPECT_EQ(spot.direction, Vec3(0, -1, 0));  // normalized
    EXPECT_EQ(spot.intensity, Vec3(3.0f));
    EXPECT_EQ(spot.inner_angle, 20.0f);
    EXPECT_EQ(spot.outer_angle, 30.0f);
}

TEST(SceneJson, BadSpotLightsAreRefusedWithTheirPath) {
    const auto spot = [](const std::string& direction, const std::string& inner,
                         const std::string& outer) {
        return error_of(R"({"lights": [{"type": "spot", "position": [0, 1, 0], "direction": )" +
                        direction + R"(, "intensity": 1, "inner_angle": )" + inner +
                        R"(, "outer_angle": )" + outer + "}]}");
    };
    EXPECT_EQ(spot("[0, -1, 0]", "30", "20"),
              "s.json: lights[0].outer_angle: outer_angle (20) must be at least inner_angle (30)");
    EXPECT_EQ(spot("[0, -1, 0]", "0", "20"),
              "s.json: lights[0].inner_angle: a spot light's half-angle must be in (0, 90] "
              "degrees, not 0");
    EXPECT_EQ(spot("[0, -1, 0]", "20", "95"),
              "s.json: lights[0].outer_angle: a spot light's half-angle must be in (0, 90] "
              "degrees, not 95");
    EXPECT_EQ(spot("[0, 0, 0]", "20", "30"),
              "s.json: lights[0].direction: expected a non-zero direction");
    EXPECT_NE(error_of(R"({"lights": [{"type": "spot", "position": [0, 1, 0],
        "direction": [0, -1, 0], "intensity": 1, "inner_angle": 20}]})")
                  .find("outer_angle"),
              std::string::npos);
}

TEST(SceneJson, BadUvsGiveJsonPath) {
    const std::string tri = R"({"objects": [{"type": "triangle",
        "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "uvs": )";
    EXPECT_EQ(error_of(tri + "[[0, 0], [1, 0]]}]}"),
              "s.json: objects[0].uvs: expected an array of 3 elements, got 2");
    EXPECT_EQ(error_of(tri + "[[0, 0], [1, 0, 0], [0, 1]]}]}"),
              "s.json: objects[0].uvs[1]: expected an array of 2 elements, got 3");
    EXPECT_EQ(error_of(tri + R"([[0, 0], [1, 0], [0, "a"]]}]})"),
              "s.json: objects[0].uvs[2][1]: expected a number, got a string");
    EXPECT_EQ(error_of(R"({"objects": [{"type": "plane", "point": [0, 0, 0],
        "normal": [0, 1, 0], "uv_scale": 0}]})"),
              "s.json: objects[0].uv_scale: expected a positive number");
}

TEST(SceneJson, UnknownKeySuggestsTheRightOne) {
    EXPECT_EQ(error_of(R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radus": 1}]})"),
              "s.json: objects[0].radus: unknown key (did you mean \"radius\"?)");
}

TEST(SceneJson, UnknownNamesAreErrors) {
    EXPECT_NE(error_of(R"({"objects": [{"type": "cube"}]})").find("unknown object type"),
              std::string::npos);
    EXPECT_NE(error_of(R"({"lights": [{"type": "laser"}], "objects": []})").find("lights[0].type"),
              std::string::npos);
    EXPECT_EQ(error_of(R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                                         "material": "gold"}]})"),
              "s.json: objects[0].material: unknown material \"gold\" (not in \"materials\")");
}

TEST(SceneJson, BadCameraIsRefused) {
    EXPECT_NE(error_of(R"({"camera": {"up": [0, 0, -1]}, "objects": []})")
                  .find("camera.up: up is parallel"),
              std::string::npos);
    EXPECT_NE(error_of(R"({"camera": {"width": 0}, "objects": []})").find("camera.width"),
              std::string::npos);
    EXPECT_NE(error_of(R"({"camera": {"fov_y": 180}, "objects": []})").find("camera.fov_y"),
              std::string::npos);
}

TEST(SceneJson, NegativeIntensityIsRefused) {
    EXPECT_EQ(error_of(R"({"lights": [{"type": "point", "position": [0, 0, 0],
                                       "intensity": [1, -1, 1]}], "objects": []})"),
              "s.json: lights[0].intensity[1]: expected a number >= 0");
}

TEST(SceneJson, EmissionMakesAMaterialALight) {
    const Scene scene = parse(R"({"materials": {"lamp": {"emission": [17, 12, 4]}},
      "objects": [{"type": "sphere", "center": [0, 0, -3], "radius": 1, "material": "lamp"}]})");
    EXPECT_EQ(scene.materials.back().emission, Vec3(17, 12, 4));
    EXPECT_NE(error_of(R"({"materials": {"lamp": {"emission": [1, -2, 0]}}, "objects": []})")
                  .find("materials.lamp.emission[1]"),
              std::string::npos);
}

TEST(SceneJson, AreaAndEnvironmentLightsParse) {
    const Scene s = testing::parse(R"({"lights": [
        {"type": "area", "corner": [0, 2, 0], "edge1": [1, 0, 0], "edge2": [0, 0, 2],
         "radiance": [1, 2, 3], "two_sided": true},
        {"type": "environment", "radiance": 0.5}], "objects": []})");
    const auto& area = std::get<AreaLight>(s.lights[0]);
    EXPECT_EQ(area.edge2, Vec3(0, 0, 2));
    EXPECT_EQ(area.radiance, Vec3(1, 2, 3));
    EXPECT_TRUE(area.two_sided);
    EXPECT_EQ(area.area_normal(), Vec3(0, -2, 0));
    const auto& env = std::get<EnvironmentLight>(s.lights[1]);
    EXPECT_EQ(env.radiance, Vec3(0.5f));
    EXPECT_EQ(env.map, nullptr);
}

TEST(SceneJson, BadAreaAndEnvironmentLightsAreRefused) {
    const auto light_error = [](const std::string& light) {
        return error_of(R"({"lights": [)" + light + R"(], "objects": []})");
    };
    const std::string degenerate =
        "s.json: lights[0]: degenerate area light: edge1 and edge2 must be nonzero and not "
        "parallel";
    EXPECT_EQ(light_error(R"({"type": "area", "corner": [0, 2, 0], "edge1": [1, 0, 0],
                              "edge2": [2, 0, 0], "radiance": 1})"),
              degenerate);
    EXPECT_EQ(light_error(R"({"type": "area", "corner": [0, 2, 0], "edge1": [0, 0, 0],
                              "edge2": [0, 0, 1], "radiance": 1})"),
              degenerate);
    EXPECT_EQ(light_error(R"({"type": "area", "corner": [0, 2, 0], "edge1": [1, 0, 0],
                              "edge2": [0, 0, 1], "radiance": [1, -2, 1]})"),
              "s.json: lights[0].radiance[1]: expected a number >= 0");
    EXPECT_EQ(light_error(R"({"type": "environment", "radiance": -1})"),
              "s.json: lights[0].radiance: expected a number >= 0");
    EXPECT_NE(light_error(R"({"type": "environment", "file": "no-such-sky.hdr"})")
                  .find("s.json: lights[0].file: cannot read environment map \"no-such-sky.hdr\""),
              std::string::npos);
    EXPECT_NE(light_error(R"({"type": "environment"})").find("exactly one of"), std::string::npos);
    EXPECT_NE(light_error(R"({"type": "environment", "radiance": 1},
                             {"type": "environment", "radiance": 1})")
                  .find("lights[1]: a scene has at most one environment light"),
              std::string::npos);
}

TEST(SceneJson, EnvironmentMapMustBeTwiceAsWideAsHigh) {
    const testing::TempDir dir;
    write_image(dir / "square.exr", Image(8, 8, Vec3(1.0f)));
    write_image(dir / "sky.exr", Image(16, 8, Vec3(1.0f)));
    std::vector<std::string> warnings;
    const auto load = [&](const std::string& file) {
        return parse_scene(R"({"lights": [{"type": "environment", "file": ")" + file +
                               R"(", "scale": 2, "rotation_degrees": 45}], "objects": []})",
                           "s.json", dir.path(), warnings);
    };
    try {
        load("square.exr");
        ADD_FAILURE() << "a square map was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(
            std::string(e.what()).find("lights[0].file: environment map \"square.exr\" is "
                                       "8x8: a latitude-longitude map is twice as wide as high"),
            std::string::npos)
            << e.what();
    }
    const Scene s = load("sky.exr");
    const auto& env = std::get<EnvironmentLight>(s.lights[0]);
    ASSERT_NE(env.map, nullptr);
    EXPECT_EQ(env.radiance, Vec3(2.0f));
    EXPECT_EQ(env.radiance_from({0, 1, 0}), Vec3(2.0f));
}

TEST(SceneJson, HugeNumbersAreRefused) {
    EXPECT_NE(error_of(R"({"ambient": 1e300, "objects": []})").find("ambient"), std::string::npos);
}

TEST(SceneJson, MissingSceneFileIsAnInputError) {
    std::vector<std::string> warnings;
    EXPECT_THROW(load_scene_file("/nonexistent/scene.json", warnings), InputError);
}

}  // namespace
}  // namespace hikari
