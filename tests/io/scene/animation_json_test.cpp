#include "hikari/io/scene/animation_json.h"

#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "../scene_test_util.h"
#include "hikari/io/scene/json_reader.h"

namespace hikari {
namespace {

using testing::error_of;
using testing::parse;

/// A scene with a sphere, a triangle, two lights and `animation` as its animation block.
std::string scene_with(const std::string& animation) {
    return fmt::format(R"({{
      "camera": {{"eye": [0, 1, 5], "look_at": [0, 0, 0]}},
      "lights": [{{"type": "point", "position": [0, 4, 0], "intensity": 10}},
                 {{"type": "environment", "radiance": 0.1}}],
      "objects": [
        {{"type": "sphere", "name": "ball", "center": [1, 0, 0], "radius": 0.5}},
        {{"type": "triangle", "name": "tri", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}],
      "animation": {}}})",
                       animation);
}

/// Frame `frame`'s document of `scene_with(animation)`.
nlohmann::json frame_of(const std::string& animation, int frame) {
    const nlohmann::json doc = nlohmann::json::parse(scene_with(animation));
    const Animation a = parse_animation(JsonNode(doc, "s.json", ""));
    return frame_document(doc, a, frame, "s.json");
}

/// Expects parsing to fail with a message holding `path` and `words`.
void expect_error(const std::string& animation, const std::string& path, const std::string& words) {
    const std::string e = error_of(scene_with(animation));
    EXPECT_NE(e.find("s.json: " + path + ": "), std::string::npos) << e;
    EXPECT_NE(e.find(words), std::string::npos) << e;
}

TEST(AnimationJson, AStillIsTheSceneAsWritten) {
    const Scene s = parse(
        scene_with(R"({"frames": 10, "camera": {"keys": [{"frame": 0, "eye": [9, 9, 9]}]}})"));
    EXPECT_EQ(s.camera.eye, Vec3(0, 1, 5));
}

TEST(AnimationJson, CameraKeysAreWrittenIntoTheCamera) {
    const nlohmann::json d = frame_of(R"({"frames": 11, "camera": {"keys": [
        {"frame": 0, "eye": [0, 1, 5], "fov_y": 30}, {"frame": 10, "eye": [10, 1, 5], "fov_y": 50}]}})",
                                      5);
    EXPECT_EQ(d["camera"]["eye"], nlohmann::json::parse("[5.0, 1.0, 5.0]"));
    EXPECT_EQ(d["camera"]["fov_y"], 40.0);
    EXPECT_EQ(d["camera"]["look_at"], nlohmann::json::parse("[0, 0, 0]"));  // not keyed
    EXPECT_FALSE(d.contains("animation"));
}

TEST(AnimationJson, ObjectStepsAreAppendedOrApplied) {
    const nlohmann::json d = frame_of(R"({"frames": 5, "objects": [
        {"object": "tri", "keys": [{"frame": 0, "translate": [0, 0, 0]},
                                   {"frame": 4, "translate": [2, 0, 0], "scale": 2}]},
        {"object": 0, "keys": [{"frame": 0, "translate": [0, 0, 0]},
                               {"frame": 4, "translate": [0, 4, 0]}]}]})",
                                      2);
    const nlohmann::json& steps = d["objects"][1]["transform"];
    ASSERT_EQ(steps.size(), 2u);
    EXPECT_EQ(steps[0]["scale"], 2.0);  // held from its only key
    EXPECT_EQ(steps[1]["translate"], nlohmann::json::parse("[1.0, 0.0, 0.0]"));
    EXPECT_EQ(d["objects"][0]["center"], nlohmann::json::parse("[1.0, 2.0, 0.0]"));
}

TEST(AnimationJson, LightsMoveTheirPoints) {
    const nlohmann::json d = frame_of(R"({"frames": 3, "lights": [{"light": 0, "keys": [
        {"frame": 0, "translate": [0, 0, 0]}, {"frame": 2, "translate": [2, 0, 0]}]}]})",
                                      1);
    EXPECT_EQ(d["lights"][0]["position"], nlohmann::json::parse("[1.0, 4.0, 0.0]"));
}

TEST(AnimationJson, BadBlocksNameTheirPath) {
    expect_error(R"({"camera": {"keys": []}})", "animation.frames", "missing");
    expect_error(R"({"frames": 0})", "animation.frames", "");
    expect_error(R"({"frames": 2, "fsp": 3})", "animation.fsp", "\"fps\"");
    expect_error(R"({"frames": 2, "interpolation": "cubic"})", "animation.interpolation",
                 "\"linear\" or \"smooth\"");
    expect_error(R"({"frames": 2, "camera": {"keys": [{"frame": 1, "eye": [0, 0, 1]},
                                                       {"frame": 1, "eye": [0, 0, 2]}]}})",
                 "animation.camera.keys[1].frame", "increasing");
    expect_error(R"({"frames": 2, "camera": {"keys": [{"frame": 0}]}})", "animation.camera.keys[0]",
                 "at least one value");
    expect_error(R"({"frames": 2, "camera": {"keys": [{"frame": 0, "fov_y": 200}]}})",
                 "animation.camera.keys[0].fov_y", "between 0 and 180");
    expect_error(R"({"frames": 2, "camera": {"keys": [{"frame": 0, "eyes": [0, 0, 1]}]}})",
                 "animation.camera.keys[0].eyes", "\"eye\"");
    expect_error(R"({"frames": 2, "objects": [{"object": "teapot", "keys": [
                     {"frame": 0, "translate": [0, 0, 0]}]}]})",
                 "animation.objects[0].object", "no object has the name \"teapot\"");
    expect_error(R"({"frames": 2, "objects": [{"object": 7, "keys": [
                     {"frame": 0, "translate": [0, 0, 0]}]}]})",
                 "animation.objects[0].object", "");
    expect_error(R"({"frames": 2, "objects": [{"object": "ball", "keys": [
                     {"frame": 0, "scale": [1, 2, 1]}]}]})",
                 "animation.objects[0].keys[0].scale", "sphere");
    expect_error(R"({"frames": 2, "objects": [
                     {"object": "ball", "keys": [{"frame": 0, "translate": [0, 0, 0]}]},
                     {"object": 0, "keys": [{"frame": 0, "translate": [0, 0, 0]}]}]})",
                 "animation.objects[1].object", "already has keys");
    expect_error(R"({"frames": 2, "lights": [{"light": 1, "keys": [
                     {"frame": 0, "translate": [0, 0, 0]}]}]})",
                 "animation.lights[0].light", "environment");
    expect_error(R"({"frames": 2, "objects": [{"object": "tri", "keys": [
                     {"frame": 0, "rotate": {"axis": [0, 0, 0], "degrees": 3}}]}]})",
                 "animation.objects[0].keys[0].rotate.axis", "");
}

}  // namespace
}  // namespace hikari
