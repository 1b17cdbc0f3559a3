// --set PATH=VALUE: scene values replaced by their JSON path before the scene is built.

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hikari/core/error.h"
#include "hikari/io/scene/scene_json.h"
#include "hikari/io/scene/scene_overrides.h"

namespace hikari {
namespace {

const std::string k_clay_spheres = R"({
  "camera": {"eye": [0, 0, 5], "fov_y": 50},
  "materials": {"clay": {"kd": [0.8, 0.5, 0.3], "ks": [0.3, 0.3, 0.3], "shininess": 20}},
  "objects": [
    {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "clay"},
    {"type": "sphere", "center": [2, 0, 0], "radius": 0.5}
  ]
})";

Scene parse_with(const std::vector<std::string>& args) {
    std::vector<SceneOverride> overrides;
    for (const std::string& a : args) overrides.push_back(parse_scene_override(a));
    std::vector<std::string> warnings;
    return parse_scene(k_clay_spheres, "s.json", ".", warnings, SceneLoadOptions(overrides));
}

std::string error_with(const std::vector<std::string>& args) {
    try {
        parse_with(args);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(SceneOverrides, SetValuesByTheirPath) {
    const Scene s = parse_with({"materials.clay.shininess=5", "camera.fov_y=30",
                                "objects[1].radius=0.25", "objects.0.center=[0,1,0]"});
    EXPECT_EQ(s.materials[0].shininess, 5.0f);
    EXPECT_EQ(s.camera.fov_y_degrees, 30.0f);
    EXPECT_EQ(s.spheres[1].radius, 0.25f);
    EXPECT_EQ(s.spheres[0].center, Vec3(0, 1, 0));
}

TEST(SceneOverrides, MissingKeysAreAddedAndBareWordsAreStrings) {
    const Scene s = parse_with({"camera.width=64", "objects[1].material=clay",
                                "background=[0.1,0.2,0.3]", "depth_cue.near=1", "depth_cue.far=9"});
    EXPECT_EQ(s.camera.width, 64);
    EXPECT_EQ(s.spheres[1].material, s.spheres[0].material);
    EXPECT_EQ(s.background, Vec3(0.1f, 0.2f, 0.3f));
    ASSERT_TRUE(s.depth_cue.has_value());
    EXPECT_EQ(s.depth_cue->far, 9.0f);
}

TEST(SceneOverrides, AMisspeltMaterialIsAnErrorNotANewMaterial) {
    EXPECT_NE(error_with({"materials.red.shininess=5"})
                  .find("materials: the scene has no material \"red\" (it has: \"clay\")"),
              std::string::npos)
        << error_with({"materials.red.shininess=5"});
}

TEST(SceneOverrides, LaterOverridesWin) {
    EXPECT_EQ(parse_with({"camera.fov_y=30", "camera.fov_y=40"}).camera.fov_y_degrees, 40.0f);
}

TEST(SceneOverrides, BadValuesAreReportedAtTheirPath) {
    EXPECT_NE(error_with({"materials.clay.shininess=-1"}).find("s.json: materials.clay.shininess:"),
              std::string::npos);
    EXPECT_NE(error_with({"camera.fovy=30"}).find("camera.fovy"), std::string::npos);
    EXPECT_NE(error_with({"objects[0].radius=big"}).find("objects[0].radius"), std::string::npos);
}

TEST(SceneOverrides, PathsThatNameNothingAreErrors) {
    EXPECT_NE(error_with({"objects[5].radius=1"})
                  .find("--set objects[5].radius=1: objects: has 2 elements, so [5] names nothing"),
              std::string::npos);
    EXPECT_NE(error_with({"camera.fov_y.x=1"}).find("camera.fov_y: is a number"),
              std::string::npos);
    EXPECT_NE(error_with({"materials[0]=1"}).find("not an array"), std::string::npos);
}

TEST(SceneOverrides, MalformedArgumentsAreRefused) {
    EXPECT_THROW(parse_scene_override("camera.fov_y"), InputError);  // no '='
    EXPECT_THROW(parse_scene_override("=5"), InputError);            // no path
    EXPECT_THROW(parse_scene_override("a..b=5"), InputError);        // empty key
    EXPECT_THROW(parse_scene_override("a[x]=5"), InputError);        // bad index
    EXPECT_THROW(parse_scene_override("a.b=[1,2"), InputError);      // bad JSON
    EXPECT_THROW(parse_scene_override("a.b=1e400"), InputError);     // out of range
    EXPECT_EQ(parse_scene_override("a.b=\"x y\"").value, "x y");
    EXPECT_EQ(parse_scene_override("a.b=true").value, true);
    EXPECT_EQ(parse_scene_override("a.b=1.5").value, 1.5);
}

}  // namespace
}  // namespace hikari
