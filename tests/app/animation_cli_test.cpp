// End-to-end checks of a scene's "animation" block through `hikari render --frames`: frame k is
// the still of the scene with frame k's values written out, bit for bit; shards and resumed runs
// give the same frames; bad blocks fail before any frame, naming their JSON path.

#include <filesystem>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "../io/temp_dir.h"
#include "hikari/session/scene_animation.h"
#include "run_hikari.h"

namespace {

namespace fs = std::filesystem;
using hikari::testing::read_text;
using hikari::testing::run_hikari;
using hikari::testing::RunResult;
using hikari::testing::TempDir;
using hikari::testing::write_text;

/// A small scene: a floor, a ball, a triangle and a point light, and `animation` as its block.
std::string scene_with(const std::string& animation) {
    return fmt::format(R"({{
      "camera": {{"eye": [0, 1, 6], "look_at": [0, 0.5, 0], "width": 64, "height": 48}},
      "ambient": 0.1,
      "lights": [{{"type": "point", "position": [0, 4, 2], "intensity": 30}}],
      "objects": [
        {{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0]}},
        {{"type": "sphere", "name": "ball", "center": [0, 0.5, 0], "radius": 0.5}},
        {{"type": "triangle", "name": "sail",
          "vertices": [[-2, 0, -1], [-1, 0, -1], [-1.5, 1.5, -1]]}}]{}}})",
                       animation.empty() ? "" : ",\n\"animation\": " + animation);
}

/// Linear keys over frames 0 to 10: at frame 5 the eye is at (2, 1, 6), the ball 1 to the
/// right, the sail turned 45° about +y and the light 1 to the right.
const std::string k_linear = R"({"frames": 11, "fps": 12,
    "camera": {"keys": [{"frame": 0, "eye": [0, 1, 6]}, {"frame": 10, "eye": [4, 1, 6]}]},
    "objects": [
      {"object": "ball", "keys": [{"frame": 0, "translate": [0, 0, 0]},
                                  {"frame": 10, "translate": [2, 0, 0]}]},
      {"object": "sail", "keys": [{"frame": 0, "rotate": {"axis": [0, 1, 0], "degrees": 0}},
                                  {"frame": 10, "rotate": {"axis": [0, 1, 0], "degrees": 90}}]}],
    "lights": [{"light": 0, "keys": [{"frame": 0, "translate": [0, 0, 0]},
                                     {"frame": 10, "translate": [2, 0, 0]}]}]})";

/// Renders `scene` (a file) as a still with `method` into `out`.
void render_still(const fs::path& scene, const std::string& method, const fs::path& out) {
    const RunResult r =
        run_hikari(fmt::format("render {} -m {} -q -o {}", scene.string(), method, out.string()));
    ASSERT_EQ(r.status, 0) << r.output;
}

TEST(AnimationCli, FrameIsTheStillOfItsValuesWrittenByHand) {
    TempDir dir;
    write_text(dir / "anim.json", scene_with(k_linear));
    const RunResult r =
        run_hikari(fmt::format("render {} -m zbuffer,raytrace --frames 5 -q -o {}",
                               (dir / "anim.json").string(), (dir / "f_%02d.png").string()));
    ASSERT_EQ(r.status, 0) << r.output;
    std::string still = scene_with("");
    const auto replace = [&still](const std::string& from, const std::string& to) {
        const size_t at = still.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        still.replace(at, from.size(), to);
    };
    replace(R"("eye": [0, 1, 6])", R"("eye": [2, 1, 6])");
    replace(R"("center": [0, 0.5, 0])", R"("center": [1, 0.5, 0])");
    replace(R"("position": [0, 4, 2])", R"("position": [1, 4, 2])");
    replace(R"("name": "sail",)",
            R"("name": "sail", "transform": [{"rotate": {"axis": [0, 1, 0], "degrees": 45}}],)");
    write_text(dir / "still.json", still);
    for (const std::string method : {"zbuffer", "raytrace"}) {
        render_still(dir / "still.json", method, dir / ("still-" + method + ".png"));
        EXPECT_EQ(read_text(dir / fmt::format("f_05-{}.png", method)),
                  read_text(dir / ("still-" + method + ".png")))
            << method;
    }
}

TEST(AnimationCli, EveryFrameIsTheStillOfItsDocument) {
    TempDir dir;
    const std::string smooth = R"({"frames": 6, "interpolation": "smooth",
        "camera": {"keys": [{"frame": 0, "eye": [0, 1, 6], "fov_y": 40},
                            {"frame": 2, "eye": [3, 2, 5]},
                            {"frame": 5, "eye": [-2, 1.5, 5], "look_at": [0, 0, 0], "fov_y": 60}]},
        "objects": [{"object": 2, "keys": [
            {"frame": 0, "scale": 1, "translate": [0, 0, 0]},
            {"frame": 3, "scale": [1, 1.5, 1], "rotate": {"axis": [1, 1, 0], "degrees": 30},
             "translate": [0.5, 0.2, 0]},
            {"frame": 5, "translate": [1, 0, 0]}]}]})";
    write_text(dir / "anim.json", scene_with(smooth));
    const RunResult r =
        run_hikari(fmt::format("render {} -m raytrace -q --frames 0-5 -o {}",
                               (dir / "anim.json").string(), (dir / "f_%d.png").string()));
    ASSERT_EQ(r.status, 0) << r.output;
    hikari::SceneSource source;
    source.file = (dir / "anim.json").string();
    const auto animation = hikari::SceneAnimation::of(source);
    ASSERT_TRUE(animation);
    for (int k = 0; k < 6; ++k) {
        const fs::path doc = dir / fmt::format("frame{}.json", k);
        write_text(doc, animation->document(k).dump());
        render_still(doc, "raytrace", dir / fmt::format("still{}.png", k));
        EXPECT_EQ(read_text(dir / fmt::format("f_{}.png", k)),
                  read_text(dir / fmt::format("still{}.png", k)))
            << "frame " << k;
    }
    EXPECT_NE(read_text(dir / "f_1.png"), read_text(dir / "f_2.png"));
}

TEST(AnimationCli, ShardsAndResumedRunsGiveTheSameFrames) {
    TempDir dir;
    write_text(dir / "anim.json", scene_with(k_linear));
    const std::string frames =
        fmt::format("render {} -m zbuffer -q --frames 2-8", (dir / "anim.json").string());
    ASSERT_EQ(run_hikari(frames + " -o " + (dir / "w_%d.png").string()).status, 0);
    for (int i = 0; i < 3; ++i)
        ASSERT_EQ(
            run_hikari(fmt::format("{} --shard {}/3 -o {}", frames, i, (dir / "s_%d.png").string()))
                .status,
            0);
    fs::remove(dir / "s_4.png");
    ASSERT_EQ(run_hikari(frames + " -o " + (dir / "s_%d.png").string()).status, 0);  // resumes
    for (int k = 2; k <= 8; ++k)
        EXPECT_EQ(read_text(dir / fmt::format("s_{}.png", k)),
                  read_text(dir / fmt::format("w_{}.png", k)))
            << k;
    EXPECT_FALSE(fs::exists(dir / "w_1.png"));
    EXPECT_FALSE(fs::exists(dir / "w_9.png"));
}

TEST(AnimationCli, BadBlocksFailBeforeAnyFrame) {
    TempDir dir;
    write_text(dir / "bad.json", scene_with(R"({"frames": 4, "objects": [{"object": "kettle",
        "keys": [{"frame": 0, "translate": [0, 0, 0]}]}]})"));
    const RunResult r = run_hikari(fmt::format(
        "render {} --frames 0-3 -o {}", (dir / "bad.json").string(), (dir / "f_%d.png").string()));
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("animation.objects[0].object: no object has the name \"kettle\""),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(dir / "f_0.png"));
    write_text(dir / "anim.json", scene_with(k_linear));
    const RunResult beyond =
        run_hikari(fmt::format("render {} --frames 5-11 -o {}", (dir / "anim.json").string(),
                               (dir / "f_%d.png").string()));
    EXPECT_EQ(beyond.status, 2) << beyond.output;
    EXPECT_NE(beyond.output.find("the scene's animation has frames 0 to 10"), std::string::npos)
        << beyond.output;
    const RunResult still = run_hikari(fmt::format(
        "render {} --frames 0-3 -o {}", (dir / "bad.json").string(), (dir / "x.png").string()));
    EXPECT_EQ(still.status, 1) << still.output;  // the load names the same path
}

}  // namespace
