// End-to-end checks of `hikari render --turntable`: each frame is the still render of its camera,
// bit for bit; a rerun skips finished frames; shards partition the frames; videos (ffprobe).

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "../io/temp_dir.h"
#include "hikari/io/images/image_read.h"
#include "hikari/scene/camera_orbit.h"
#include "hikari/session/session.h"
#include "run_hikari.h"

namespace {

namespace fs = std::filesystem;
using hikari::testing::read_text;
using hikari::testing::run_hikari;
using hikari::testing::run_shell;
using hikari::testing::RunResult;
using hikari::testing::TempDir;

/// The small still every test renders: the default scene by the Z-buffer.
const std::string k_still = "render --width 48 -m zbuffer -q";

/// The files of `dir` by name.
std::set<std::string> names_in(const fs::path& dir) {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
    return names;
}

TEST(FramesCli, TurntableFrameIsTheStillOfItsCamera) {
    TempDir dir;
    const int n = 5;
    const RunResult frames =
        run_hikari(fmt::format("render --width 48 -m zbuffer,raytrace --turntable {} -o {}", n,
                               (dir / "f_%02d.png").string()));
    ASSERT_EQ(frames.status, 0) << frames.output;
    hikari::Session session{hikari::SceneSource{}};
    const hikari::Camera base = hikari::resized_camera(session.scene().camera, 48, 0);
    for (int k = 0; k < n; ++k) {
        const hikari::Camera c = hikari::turntable_camera(base, k, n);
        for (const std::string method : {"zbuffer", "raytrace"}) {
            const fs::path still = dir / fmt::format("still_{}_{}.png", k, method);
            const RunResult r = run_hikari(fmt::format(
                "render --width 48 -m {} --camera-from={},{},{} --look-at={},{},{} -o {}", method,
                c.eye.x, c.eye.y, c.eye.z, c.look_at.x, c.look_at.y, c.look_at.z, still.string()));
            ASSERT_EQ(r.status, 0) << r.output;
            const fs::path frame = dir / fmt::format("f_{:02d}-{}.png", k, method);
            EXPECT_EQ(read_text(frame), read_text(still)) << frame;
        }
    }
    // The frames differ from each other: the camera moved.
    EXPECT_NE(read_text(dir / "f_00-zbuffer.png"), read_text(dir / "f_01-zbuffer.png"));
}

TEST(FramesCli, RerunSkipsFinishedFramesAndOverwriteRendersThem) {
    TempDir dir;
    const std::string args = k_still + " --turntable 4 -o " + (dir / "f_%d.png").string();
    ASSERT_EQ(run_hikari(args).status, 0);
    const std::string frame2 = read_text(dir / "f_2.png");
    hikari::testing::write_text(dir / "f_2.png", "left by an earlier run");
    fs::remove(dir / "f_1.png");
    const RunResult resumed = run_hikari(args + " --frames 0-3");
    ASSERT_EQ(resumed.status, 0) << resumed.output;
    EXPECT_EQ(read_text(dir / "f_2.png"), "left by an earlier run");  // skipped
    EXPECT_TRUE(fs::exists(dir / "f_1.png"));                         // rendered again
    const RunResult loud =
        run_hikari("render --width 48 -m zbuffer --turntable 4 -o " + (dir / "f_%d.png").string());
    EXPECT_NE(loud.output.find("wrote 0 frames"), std::string::npos) << loud.output;
    EXPECT_NE(loud.output.find("4 already there"), std::string::npos) << loud.output;
    ASSERT_EQ(run_hikari(args + " --overwrite").status, 0);
    EXPECT_EQ(read_text(dir / "f_2.png"), frame2);
    EXPECT_EQ(names_in(dir.path()).size(), 4u);  // no temporaries left
}

TEST(FramesCli, ShardsPartitionTheFramesWhateverTheThreads) {
    TempDir dir;
    fs::create_directories(dir / "whole");
    fs::create_directories(dir / "shards");
    const std::string frames = k_still + " --turntable 7 --frames 1-6";
    ASSERT_EQ(run_hikari(frames + " -o " + (dir / "whole" / "f_%03d.png").string()).status, 0);
    for (int i = 0; i < 4; ++i) {
        const RunResult r =
            run_hikari(fmt::format("{} --shard {}/4 --threads {} -o {}", frames, i, 1 + i % 2,
                                   (dir / "shards" / "f_%03d.png").string()));
        ASSERT_EQ(r.status, 0) << r.output;
        const size_t written_so_far[] = {2, 4, 5, 6};  // 6 frames in 4 shards: 2, 2, 1, 1
        EXPECT_EQ(names_in(dir / "shards").size(), written_so_far[i]);
    }
    const std::set<std::string> names = names_in(dir / "whole");
    ASSERT_EQ(names.size(), 6u);
    EXPECT_EQ(names_in(dir / "shards"), names);
    for (const std::string& name : names)
        EXPECT_EQ(read_text(dir / "shards" / name), read_text(dir / "whole" / name)) << name;
}

TEST(FramesCli, VideosHaveEveryFrameAtTheImageSize) {
    if (run_shell("command -v ffmpeg && command -v ffprobe").status != 0)
        GTEST_SKIP() << "ffmpeg and ffprobe are not installed (apt-get install ffmpeg)";
    TempDir dir;
    for (const std::string name : {"t.mp4", "t.webm", "t.gif"}) {
        const fs::path video = dir / name;
        const RunResult r = run_hikari(
            "render --width 64 --height 48 -m zbuffer -q "
            "--turntable 12 --fps 24 -o " +
            video.string());
        ASSERT_EQ(r.status, 0) << r.output;
        const RunResult probe = run_shell(
            "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
            "stream=nb_read_frames,width,height -of csv=p=0 " +
            video.string());
        ASSERT_EQ(probe.status, 0) << probe.output;
        EXPECT_EQ(probe.output, "64,48,12\n") << name;
    }
    EXPECT_EQ(names_in(dir.path()).size(), 3u);  // the videos and no temporaries
}

TEST(FramesCli, VideoWithoutFfmpegSaysHowToGetIt) {
    TempDir dir;
    const RunResult r =
        run_shell(fmt::format("PATH={} {} {} --turntable 4 -o {}", dir.path().string(),
                              HIKARI_CLI_PATH, k_still, (dir / "t.mp4").string()));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("apt-get install ffmpeg"), std::string::npos) << r.output;
    EXPECT_EQ(names_in(dir.path()).size(), 0u);
}

TEST(FramesCli, BadFrameOptionsAreClearErrors) {
    TempDir dir;
    const std::string out = (dir / "f_%04d.png").string();
    const auto expect = [&](const std::string& args, int status, const std::string& message) {
        const RunResult r = run_hikari(k_still + " " + args);
        EXPECT_EQ(r.status, status) << args << ": " << r.output;
        EXPECT_NE(r.output.find(message), std::string::npos) << args << ": " << r.output;
    };
    expect("--turntable 4 -o " + (dir / "f.png").string(), 2, "needs a frame number");
    expect("--turntable 4 -o " + (dir / "f_%04d_%d.png").string(), 2, "two frame numbers");
    expect("--turntable 4", 2, "-o");
    expect("--turntable 6 --frames 5-9 -o " + out, 2, "frames 0 to 5");
    expect("--turntable 6 --frames 4-2 -o " + out, 2, "before the first");
    expect("--turntable 6 --shard 3/3 -o " + out, 2, "0 to N-1");
    expect("--turntable 6 --shard 1 -o " + out, 2, "I/N");
    expect("--frames 1-2 -o " + out, 2, "add --turntable");
    expect("-o " + (dir / "t.mp4").string(), 2, "a video needs frames");
    expect("--turntable 6 --shard 0/2 -o " + (dir / "t.mp4").string(), 2, "--shard");
    expect("--turntable 0 -o " + out, 2, "--turntable");
    expect("--turntable 2 -o " + (dir / "f_%d.svg").string(), 2, "draws no lines");
    expect("--turntable 2 -o " + (dir / "no" / "f_%d.png").string(), 2, "does not exist");
    expect("--turntable 2 -o " + out + " " + (dir / "missing.json").string(), 1, "missing.json");
    EXPECT_EQ(names_in(dir.path()).size(), 0u);
}

TEST(FramesCli, SideBySideFrameIsEveryMethodsFrameUnderItsName) {
    TempDir dir;
    const std::string turntable = "render --width 48 -m zbuffer,raytrace -q --turntable 3 ";
    ASSERT_EQ(run_hikari(turntable + "-o " + (dir / "f_%d.png").string()).status, 0);
    for (const int threads : {1, 2}) {
        const RunResult r =
            run_hikari(fmt::format("{} --side-by-side --threads {} -o {}", turntable, threads,
                                   (dir / fmt::format("t{}_%d.png", threads)).string()));
        ASSERT_EQ(r.status, 0) << r.output;
    }
    for (int k = 0; k < 3; ++k) {
        // The same bits whatever the thread count.
        EXPECT_EQ(read_text(dir / fmt::format("t1_{}.png", k)),
                  read_text(dir / fmt::format("t2_{}.png", k)));
        const hikari::Image both = hikari::read_image(dir / fmt::format("t1_{}.png", k));
        const hikari::Image z = hikari::read_image(dir / fmt::format("f_{}-zbuffer.png", k));
        const hikari::Image r = hikari::read_image(dir / fmt::format("f_{}-raytrace.png", k));
        ASSERT_EQ(both.width, 2 * 48 + 2);  // two panels, a gap of 2
        const int strip = both.height - z.height;
        ASSERT_EQ(strip, 12);  // the labels at the font's size: doubled, they are too wide
        size_t ink = 0;
        for (int y = 0; y < strip; ++y)
            for (int x = 0; x < both.width; ++x) ink += both.at(x, y).x < 0.1f;
        EXPECT_GT(ink, 40u) << "the labels";
        for (int y = 0; y < z.height; ++y)
            for (int x = 0; x < 48; ++x) {
                ASSERT_EQ(both.at(x, strip + y), z.at(x, y)) << k << ": " << x << "," << y;
                ASSERT_EQ(both.at(x + 50, strip + y), r.at(x, y)) << k;
            }
    }
}

TEST(FramesCli, SideBySideVideoIsOneVideoOfThePanels) {
    if (run_shell("command -v ffmpeg && command -v ffprobe").status != 0)
        GTEST_SKIP() << "ffmpeg and ffprobe are not installed (apt-get install ffmpeg)";
    TempDir dir;
    const RunResult r = run_hikari(
        "render --width 64 --height 48 -m wireframe,zbuffer -q --side-by-side --turntable 6 -o " +
        (dir / "t.mp4").string());
    ASSERT_EQ(r.status, 0) << r.output;
    const RunResult probe = run_shell(
        "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
        "stream=nb_read_frames,width,height -of csv=p=0 " +
        (dir / "t.mp4").string());
    EXPECT_EQ(probe.output, "130,60,6\n");  // 64 + 2 + 64 wide, 48 + a 12-pixel label strip
    EXPECT_EQ(names_in(dir.path()).size(), 1u);
}

TEST(FramesCli, SideBySideMistakesAreUsageErrors) {
    TempDir dir;
    const auto expect = [&](const std::string& args, const std::string& message) {
        const RunResult r = run_hikari("render --width 48 -m zbuffer,raytrace -q " + args);
        EXPECT_EQ(r.status, 2) << args << ": " << r.output;
        EXPECT_NE(r.output.find(message), std::string::npos) << args << ": " << r.output;
    };
    expect("--side-by-side -o " + (dir / "s.png").string(), "add --turntable");
    expect("--side-by-side --turntable 3 -o " + (dir / "s_%d.pfm").string(), "8-bit pictures");
    expect("--side-by-side --turntable 3 -o " + (dir / "s_%d.svg").string(), "8-bit pictures");
    expect("--side-by-side --turntable 3 -o " + (dir / "s.png").string(), "frame number");
    EXPECT_EQ(names_in(dir.path()).size(), 0u);
}

}  // namespace
