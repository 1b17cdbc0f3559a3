// End-to-end checks of the hikari program: exit statuses, messages and files written.

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "../io/temp_dir.h"
#include "hikari/core/image.h"
#include "hikari/io/images/image_read.h"

#include "run_hikari.h"

namespace {

namespace fs = std::filesystem;

using Result = hikari::testing::RunResult;
constexpr auto run = hikari::testing::run_hikari;

class Cli : public ::testing::Test {
  protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() /
                ("hikari_cli_" +
                 std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }

    std::string path(const std::string& name) const { return (m_dir / name).string(); }
    void write(const std::string& name, const std::string& text) const {
        std::ofstream(m_dir / name) << text;
    }
    size_t file_count() const {
        return static_cast<size_t>(std::distance(fs::directory_iterator(m_dir), {}));
    }
    /// `render ARGS -o out.png` exits 2 with "hikari: error: MESSAGE".
    void expect_usage_error(const std::string& args, const std::string& message) const {
        const Result r = run("render " + args + " -o " + path("out.png"));
        EXPECT_EQ(r.status, 2) << args << ": " << r.output;
        EXPECT_NE(r.output.find("hikari: error: " + message), std::string::npos) << r.output;
    }

    fs::path m_dir;
};

TEST_F(Cli, VersionAndHelpSucceed) {
    EXPECT_EQ(run("--version").status, 0);
    const Result help = run("render --help");
    EXPECT_EQ(help.status, 0);
    EXPECT_NE(help.output.find("raytrace"), std::string::npos);
}

TEST_F(Cli, DefaultSceneRendersToPng) {
    const Result r = run("render --width 64 -o " + path("sphere.png"));
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(fs::exists(path("sphere.png")));
    EXPECT_GT(fs::file_size(path("sphere.png")), 100u);
}

TEST_F(Cli, UsageErrorsExitWithTwo) {
    EXPECT_EQ(run("render --spp 0").status, 2);
    EXPECT_EQ(run("render --method nonsense").status, 2);
    EXPECT_EQ(run("render --no-such-flag").status, 2);
    EXPECT_EQ(run("").status, 2);
}

TEST_F(Cli, BadSceneExitsWithOneAndWritesNothing) {
    write("bad.json", "{\"objects\": [ {\"type\": \"sphere\", \"radius\": 1,} ]}");
    const Result r = run(path("bad.json") + " -o " + path("out.png"));
    EXPECT_EQ(r.status, 2) << "scene file given without the render subcommand is a usage error";
    const Result bad = run("render " + path("bad.json") + " -o " + path("out.png"));
    EXPECT_EQ(bad.status, 1) << bad.output;
    EXPECT_EQ(bad.output.rfind("hikari: error: ", 0), 0u) << bad.output;
    EXPECT_NE(bad.output.find("bad.json:1:"), std::string::npos) << bad.output;
    EXPECT_EQ(file_count(), 1u);  // only bad.json
}

TEST_F(Cli, RefusesToOverwriteTheSceneFile) {
    const std::string scene = R"({"objects": [{"type": "sphere", "center": [0, 0, -3]}]})";
    write("scene.png", scene);
    const Result r = run("render " + path("scene.png") + " --width 8 -o " + path("scene.png"));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("refusing to overwrite the scene file"), std::string::npos) << r.output;
    EXPECT_EQ(hikari::testing::read_text(path("scene.png")), scene);
}

TEST_F(Cli, MissingSceneFileExitsWithOne) {
    const Result r = run("render " + path("missing.json") + " -o " + path("out.png"));
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("missing.json"), std::string::npos);
    EXPECT_FALSE(fs::exists(path("out.png")));
}

TEST_F(Cli, UnsupportedOutputFormatIsRefusedBeforeRendering) {
    const Result r = run("render -o " + path("out.gif"));
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("out.gif"), std::string::npos);
    EXPECT_EQ(file_count(), 0u);
}

TEST_F(Cli, OversizedRenderIsRefused) {
    const Result r = run("render --width 60000 --height 60000 --max-memory 1 -o " + path("x.png"));
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("max-memory"), std::string::npos);
    EXPECT_EQ(file_count(), 0u);
}

TEST_F(Cli, PfmOutputHoldsLinearFloats) {
    const Result r = run("render --width 8 --height 8 -o " + path("x.pfm"));
    ASSERT_EQ(r.status, 0) << r.output;
    std::ifstream in(path("x.pfm"), std::ios::binary);
    std::string magic;
    in >> magic;
    EXPECT_EQ(magic, "PF");
    EXPECT_EQ(fs::file_size(path("x.pfm")), std::string("PF\n8 8\n-1.0\n").size() + 8 * 8 * 12);
}

TEST_F(Cli, OutputIntoMissingDirectoryIsRefusedBeforeRendering) {
    const Result r = run("render -o " + path("no/such/dir/x.png"));
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("does not exist"), std::string::npos) << r.output;
}

TEST_F(Cli, InterruptStopsTheRenderAndWritesNothing) {
    const std::string output = path("long.png");
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        // A render that would take minutes.
        execl(HIKARI_CLI_PATH, HIKARI_CLI_PATH, "render", "--spp", "4096", "--width", "1024", "-q",
              "-o", output.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1000));
    kill(child, SIGINT);
    int raw = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (waitpid(child, &raw, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() > deadline) {
            kill(child, SIGKILL);
            waitpid(child, &raw, 0);
            FAIL() << "the render did not stop within 20 s of SIGINT";
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ASSERT_TRUE(WIFEXITED(raw)) << "killed by signal " << WTERMSIG(raw);
    EXPECT_EQ(WEXITSTATUS(raw), 130);
    EXPECT_EQ(file_count(), 0u) << "no output and no temporary file may be left";
}

}  // namespace

namespace {

TEST_F(Cli, RasterOptionsRenderAndRejectBadValues) {
    const Result ok = run("render --method zbuffer --interp gouraud --cull back --width 32 -q -o " +
                          path("z.png"));
    EXPECT_EQ(ok.status, 0) << ok.output;
    EXPECT_TRUE(fs::exists(path("z.png")));
    EXPECT_EQ(run("render --method zbuffer --interp smooth -o " + path("a.png")).status, 2);
    EXPECT_EQ(run("render --method zbuffer --cull front -o " + path("b.png")).status, 2);
    EXPECT_EQ(file_count(), 1u);
}

// An option the chosen method does not understand is a usage error that names it and the
// method, before anything is written; both ways round.
TEST_F(Cli, OptionForeignToTheMethodExitsTwoAndWritesNothing) {
    expect_usage_error("--interp flat --width 16",
                       "--interp is not an option of method raytrace (it understands: --spp, "
                       "--max-depth, --shadows, --light-samples, --device)");
    expect_usage_error(
        "-m zbuffer --max-depth 4 --width 16",
        "--max-depth is not an option of method zbuffer (it understands: --spp, --interp, "
        "--cull, --shadows, --shadow-map-size, --light-samples, --device)");
    expect_usage_error("-m depthsort --max-depth 2",
                       "--max-depth is not an option of method depthsort");
    expect_usage_error("-m raytrace --cull back", "--cull is not an option of method raytrace");
    expect_usage_error("-m wireframe --shadows map",
                       "--shadows is not an option of method wireframe");
    EXPECT_EQ(file_count(), 0u);
}

TEST_F(Cli, ShadowModeAMethodCannotDrawExitsTwo) {
    const auto expect_refused = [&](const std::string& args, const std::string& message) {
        expect_usage_error(args + " --width 16", message);
    };
    expect_refused("--shadows map",
                   "--shadows map: method raytrace cannot draw shadows that way (it can: ray, "
                   "analytic, none)");
    expect_refused("-m scanline --shadows ray",
                   "--shadows ray: method scanline cannot draw shadows that way (it can: map, "
                   "volume, pcf, pcss, analytic, none)");
    expect_refused("-m zbuffer --shadows soft",
                   "--shadows: soft not in {none,ray,map,volume,pcf,pcss,analytic}");
    EXPECT_EQ(file_count(), 0u);
    for (const char* ok : {"--shadows none", "-m zbuffer --shadows volume",
                           "-m depthsort --shadows map --shadow-map-size 64"}) {
        const Result r = run(std::string("render ") + ok + " --width 16 -q -o " + path("ok.png"));
        EXPECT_EQ(r.status, 0) << ok << ": " << r.output;
    }
}

TEST_F(Cli, LineMethodsWriteSvg) {
    const std::string scene = std::string(HIKARI_SOURCE_DIR) + "/scenes/teapot.json";
    for (const char* method : {"wireframe", "hiddenline"}) {
        const Result r = run("render " + scene + " -m " + method +
                             " --width 80 --line-width 2 --line-color 1,0,0 --cull back -q -o " +
                             path(std::string(method) + ".svg"));
        EXPECT_EQ(r.status, 0) << r.output;
        const std::string svg = hikari::testing::read_text(path(std::string(method) + ".svg"));
        EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
        EXPECT_NE(svg.find(R"(viewBox="0 0 80 60")"), std::string::npos);
        EXPECT_NE(svg.find(R"(stroke-width="2")"), std::string::npos);
        EXPECT_NE(svg.find(R"(<line )"), std::string::npos);
        EXPECT_NE(svg.find(R"(stroke="#ff0000")"), std::string::npos);
    }
    EXPECT_EQ(file_count(), 2u);
}

TEST_F(Cli, SvgForAnotherMethodIsAnErrorAndWritesNothing) {
    for (const char* method : {"raytrace", "zbuffer", "depthsort"}) {
        const Result r =
            run(std::string("render --width 16 -m ") + method + " -o " + path("x.svg"));
        EXPECT_EQ(r.status, 2) << r.output;  // an -o mistake: a usage error
        EXPECT_EQ(r.output.rfind("hikari: error: ", 0), 0u) << r.output;
        EXPECT_NE(r.output.find("SVG output is for the line methods"), std::string::npos)
            << r.output;
    }
    const Result depth = run("render --width 16 -m wireframe --aov depth -o " + path("x.svg"));
    EXPECT_EQ(depth.status, 2) << depth.output;
    EXPECT_EQ(file_count(), 0u);
}

TEST_F(Cli, LineOptionsAreCheckedAndBelongToTheLineMethods) {
    EXPECT_EQ(run("render -m wireframe --line-width 0 -o " + path("a.png")).status, 2);
    EXPECT_EQ(run("render -m wireframe --line-color 1,0 -o " + path("a.png")).status, 2);
    EXPECT_EQ(run("render -m wireframe --line-color 1,-1,0 -o " + path("a.png")).status, 2);
    const Result foreign = run("render -m zbuffer --line-width 2 -o " + path("a.png"));
    EXPECT_EQ(foreign.status, 2);
    EXPECT_NE(foreign.output.find("--line-width is not an option of method zbuffer"),
              std::string::npos)
        << foreign.output;
    const Result ok =
        run("render -m hiddenline --width 24 --line-width 0.5 -q -o " + path("ok.png"));
    EXPECT_EQ(ok.status, 0) << ok.output;
    EXPECT_EQ(file_count(), 1u);
}

TEST_F(Cli, HelpSaysWhichMethodsTakeWhichOptions) {
    const Result help = run("render --help");
    EXPECT_EQ(help.status, 0);
    for (const char* option : {"--spp", "--max-depth", "--interp", "--cull", "--aov", "--width"})
        EXPECT_NE(help.output.find(option), std::string::npos) << option;
    EXPECT_NE(help.output.find("options: --spp, --max-depth"), std::string::npos) << help.output;
    EXPECT_NE(help.output.find("options: --spp, --interp, --cull"), std::string::npos)
        << help.output;
    EXPECT_NE(help.output.find("options: --line-width, --line-color, --cull"), std::string::npos)
        << help.output;
}

TEST_F(Cli, StatsReportRaysAndBvh) {
    write("tri.json", R"({"camera": {"width": 8, "height": 8}, "objects": [
        {"type": "triangle", "vertices": [[-1, -1, -2], [1, -1, -2], [0, 1, -2]]}]})");
    const Result r = run("render " + path("tri.json") + " --stats -o " + path("t.png"));
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("Mrays/s"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("BVH 1 triangles"), std::string::npos) << r.output;
}

TEST_F(Cli, BenchPrintsOneJsonObject) {
    write("quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
    const Result r =
        run("bench B1 --mesh " + path("quad.obj") + " --threads 2 --reps 1 2>/dev/null");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output.front(), '{');
    for (const char* key : {"\"bench\": \"B1\"", "\"mesh\": \"quad\"", "\"threads\": 2",
                            "\"mrays_per_s\"", "\"build_ms\"", "\"hits\"", "\"mean_t\""})
        EXPECT_NE(r.output.find(key), std::string::npos) << key << " in " << r.output;
    const Result b2 = run("bench B2 --mesh " + path("quad.obj") + " --reps 1 2>/dev/null");
    EXPECT_NE(b2.output.find("\"occluded_fraction\""), std::string::npos) << b2.output;
}

TEST_F(Cli, BenchB4DrawsTheFrameAndWritesIt) {
    // A quad filling the middle of the SPEC's view: B1 camera at 1.1 diagonals.
    write("quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
    const Result r = run("bench B4 --mesh " + path("quad.obj") +
                         " --threads 2 --reps 1 --shadow -o " + path("frame.png") + " 2>/dev/null");
    EXPECT_EQ(r.status, 0) << r.output;
    for (const char* key : {"\"bench\": \"B4\"", "\"mesh\": \"quad\"", "\"threads\": 2",
                            "\"variant\": \"shadow\"", "\"ms_per_frame\"", "\"covered_pixels\""})
        EXPECT_NE(r.output.find(key), std::string::npos) << key << " in " << r.output;
    EXPECT_EQ(r.output.find("\"covered_pixels\": 0,"), std::string::npos) << r.output;
    EXPECT_TRUE(std::filesystem::exists(path("frame.png")));
    // An output it cannot write is refused before any frame is drawn.
    const Result bad = run("bench B4 --mesh " + path("quad.obj") + " -o " + path("frame.bmp"));
    EXPECT_EQ(bad.status, 1) << bad.output;
    EXPECT_NE(bad.output.find("unsupported output format"), std::string::npos) << bad.output;
}

TEST_F(Cli, BenchUsageErrorsExitTwo) {
    EXPECT_EQ(run("bench B9 --mesh x.obj").status, 2);
    EXPECT_EQ(run("bench B1").status, 2);
    write("quad.obj", "v 0 0 0\n");
    EXPECT_EQ(run("bench B1 --mesh " + path("quad.obj") + " --threads 0").status, 2);
}

// A mesh that cannot be used is bad input, as a scene file is: one line naming it, status 1.
TEST_F(Cli, BenchInputErrorsExitOne) {
    write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    write("bad_face.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n");
    write("far_vertex.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n");
    write("before_first.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -9\n");
    const std::pair<std::string, std::string> cases[] = {
        {path("missing.obj"), "cannot read"},
        {m_dir.string(), "cannot read"},
        {path("points.obj"), "no triangles"},
        {path("bad_face.obj"), "line 4"},
        {path("far_vertex.obj"), "triangle 2 refers to a vertex out of range"},
        {path("before_first.obj"), "triangle 1 refers to a vertex out of range"},
    };
    for (const auto& [mesh, reason] : cases) {
        const Result r = run("bench B1 --reps 1 --mesh " + mesh);
        EXPECT_EQ(r.status, 1) << mesh << ": " << r.output;
        EXPECT_EQ(r.output.rfind("hikari: error: " + mesh + ": ", 0), 0u) << r.output;
        EXPECT_NE(r.output.find(reason), std::string::npos) << r.output;
        EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << "one line: " << r.output;
    }
}

// More threads than the machine has cores: the build and the trace run that many, and nothing
// but the JSON object is printed (TBB warns when an arena asks for more than its pool allows).
TEST_F(Cli, BenchWithMoreThreadsThanCoresPrintsOnlyJson) {
    write("quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
    const Result r = run("bench B1 --mesh " + path("quad.obj") + " --threads 64 --reps 1");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output.front(), '{') << r.output;
    EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << r.output;
    EXPECT_NE(r.output.find("\"threads\": 64"), std::string::npos) << r.output;
}

}  // namespace

namespace hikari {
namespace {

/// A small scene with near and far objects, a flat background and a textured floor.
constexpr const char* k_cue_scene = R"({
  "camera": {"eye": [0, 2, 8], "look_at": [0, 1, 0], "fov_y": 50, "width": 48, "height": 32},
  "background": [0.1, 0.2, 0.3], "ambient": 0.2,
  "materials": {"floor": {"ka": 0.3, "kd": 0.7, "texture": {"type": "checker", "size": 1}},
                "ball": {"ka": 0.2, "kd": 0.6, "ks": 0.4, "shininess": 20}},
  "lights": [{"type": "point", "position": [3, 6, 4], "intensity": 60}],
  "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
              {"type": "sphere", "center": [-1, 1, 2], "radius": 1, "material": "ball"},
              {"type": "sphere", "center": [2, 1, -6], "radius": 1, "material": "ball"}]})";

TEST_F(Cli, DepthCueFollowsTheLecturesBlendForEveryMethod) {
    write("scene.json", k_cue_scene);
    for (const char* method : {"raytrace", "zbuffer", "scanline", "depthsort"}) {
        SCOPED_TRACE(method);
        const std::string m = std::string(" -m ") + method +
                              (method == std::string("raytrace") ? "" : " --shadow-map-size 256") +
                              " -q -o ";
        ASSERT_EQ(run("render " + path("scene.json") + m + path("plain.pfm")).status, 0);
        ASSERT_EQ(
            run("render " + path("scene.json") + m + path("depth.pfm") + " --aov depth").status, 0);
        ASSERT_EQ(
            run("render " + path("scene.json") + m + path("cued.pfm") + " --depth-cue 6,14").status,
            0);
        const Image plain = read_image(path("plain.pfm")), depth = read_image(path("depth.pfm")),
                    cued = read_image(path("cued.pfm"));
        ASSERT_EQ(cued.pixels.size(), plain.pixels.size());
        int blended = 0;
        for (size_t i = 0; i < plain.pixels.size(); ++i) {
            const float d = depth.pixels[i].x;
            const float w = std::clamp((14.0f - d) / (14.0f - 6.0f), 0.0f, 1.0f);
            blended += w > 0.0f && w < 1.0f ? 1 : 0;
            const Vec3 background(0.1f, 0.2f, 0.3f);
            for (int a = 0; a < 3; ++a)
                ASSERT_NEAR(cued.pixels[i][a], w * plain.pixels[i][a] + (1 - w) * background[a],
                            1e-4f)
                    << "pixel " << i;
        }
        EXPECT_GT(blended, 50);  // the floor and the far ball lie between NEAR and FAR
    }
}

TEST_F(Cli, DepthCueMistakesAreErrors) {
    write("scene.json", k_cue_scene);
    const Result reversed =
        run("render " + path("scene.json") + " --depth-cue 5,2 -o " + path("out.png"));
    EXPECT_EQ(reversed.status, 2);
    EXPECT_NE(reversed.output.find("FAR must be greater than NEAR"), std::string::npos);
    std::string bad = k_cue_scene;
    bad.insert(1, R"("depth_cue": {"near": 5, "far": 5},)");
    write("bad.json", bad);
    const Result equal = run("render " + path("bad.json") + " -o " + path("out.png"));
    EXPECT_EQ(equal.status, 1);
    EXPECT_NE(equal.output.find("depth_cue.far: far must be greater than near"), std::string::npos)
        << equal.output;
    EXPECT_EQ(file_count(), 2u);  // the two scene files: no image written
}

TEST_F(Cli, BadLightsExitOneAndWriteNothing) {
    write("area.json", R"({"lights": [{"type": "area", "corner": [0, 2, 0], "edge1": [1, 0, 0],
        "edge2": [-2, 0, 0], "radiance": 1}], "objects": []})");
    const Result area = run("render " + path("area.json") + " -o " + path("out.png"));
    EXPECT_EQ(area.status, 1);
    EXPECT_NE(area.output.find("hikari: error: "), std::string::npos) << area.output;
    EXPECT_NE(area.output.find("lights[0]: degenerate area light"), std::string::npos)
        << area.output;
    write("sky.json",
          R"({"lights": [{"type": "environment", "file": "missing.hdr"}], "objects": []})");
    const Result sky = run("render " + path("sky.json") + " -o " + path("out.png"));
    EXPECT_EQ(sky.status, 1);
    EXPECT_NE(sky.output.find("lights[0].file: cannot read environment map"), std::string::npos)
        << sky.output;
    write("bad.hdr", "#?RADIANCE\nnot really\n");
    write("garbled.json",
          R"({"lights": [{"type": "environment", "file": "bad.hdr"}], "objects": []})");
    const Result garbled = run("render " + path("garbled.json") + " -o " + path("out.png"));
    EXPECT_EQ(garbled.status, 1) << garbled.output;
    EXPECT_EQ(file_count(), 4u);  // the scene files and bad.hdr: no image
}

TEST_F(Cli, LightSamplesAndSoftShadowModesRender) {
    write("area.json", R"({"camera": {"width": 16, "height": 16, "eye": [0, 3, 3]},
        "lights": [{"type": "area", "corner": [-0.5, 2, -0.5], "edge1": [1, 0, 0],
                    "edge2": [0, 0, 1], "radiance": 4}],
        "objects": [{"type": "sphere", "center": [0, 0.5, 0], "radius": 0.5},
                    {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0]}]})");
    for (const char* args : {"-m raytrace --light-samples 4", "-m raytrace --shadows analytic",
                             "-m zbuffer --shadows pcf", "-m scanline --shadows pcss",
                             "-m depthsort --shadows analytic"}) {
        const Result r = run("render " + path("area.json") + " " + args + " -o " + path("a.png"));
        EXPECT_EQ(r.status, 0) << args << ": " << r.output;
    }
    expect_usage_error(path("area.json") + " --light-samples 0", "--light-samples");
    expect_usage_error(path("area.json") + " -m raytrace --shadows pcss",
                       "--shadows pcss: method raytrace cannot draw shadows that way");
}

TEST_F(Cli, RendersIntoASpreadsheet) {
    const Result r = run("render --width 16 --height 12 -o " + path("sphere.xlsx"));
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(hikari::testing::read_text(path("sphere.xlsx")).substr(0, 2), "PK");
    const Result wide = run("render --width 16385 --height 1 -o " + path("wide.xlsx"));
    EXPECT_EQ(wide.status, 1) << wide.output;
    EXPECT_NE(wide.output.find("does not fit a spreadsheet (at most 16384 columns"),
              std::string::npos)
        << wide.output;
    EXPECT_EQ(file_count(), 1u);
}

TEST_F(Cli, RendersJpegAndRadianceHdr) {
    const Result jpg = run("render --width 32 --height 24 -q -o " + path("x.jpg"));
    ASSERT_EQ(jpg.status, 0) << jpg.output;
    EXPECT_EQ(hikari::testing::read_text(path("x.jpg")).substr(0, 3), "\xFF\xD8\xFF");
    EXPECT_EQ(hikari::read_image(path("x.jpg")).width, 32);
    ASSERT_EQ(run("render --width 32 --height 24 -q -o " + path("x.pfm")).status, 0);
    const Result hdr = run("render --width 32 --height 24 -q -o " + path("x.hdr"));
    ASSERT_EQ(hdr.status, 0) << hdr.output;
    const hikari::Image linear = hikari::read_image(path("x.pfm")),
                        rgbe = hikari::read_image(path("x.hdr"));
    ASSERT_EQ(rgbe.pixels.size(), linear.pixels.size());
    for (size_t i = 0; i < linear.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(rgbe.pixels[i][c], linear.pixels[i][c], 0.01f) << i;
}

TEST_F(Cli, BitDepthSixteenIsForPngAndPpm) {
    const Result r = run("render --width 16 --height 12 -q --bit-depth 16 -o " + path("x.png"));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(static_cast<uint8_t>(hikari::testing::read_text(path("x.png"))[24]), 16);
    ASSERT_EQ(run("render --width 16 --height 12 -q -o " + path("y.png")).status, 0);
    const hikari::Image deep = hikari::read_image(path("x.png")),
                        shallow = hikari::read_image(path("y.png"));
    for (size_t i = 0; i < deep.pixels.size(); ++i)
        ASSERT_NEAR(deep.pixels[i].x, shallow.pixels[i].x, 0.01f) << i;
    const Result exr = run("render --bit-depth 16 -o " + path("x.exr"));
    EXPECT_EQ(exr.status, 2) << exr.output;
    EXPECT_NE(exr.output.find("hikari: error: --bit-depth 16: " + path("x.exr")), std::string::npos)
        << exr.output;
    EXPECT_EQ(run("render --bit-depth 16 -o " + path("x.jpg")).status, 2);
    expect_usage_error("--bit-depth 12", "--bit-depth: expected 8 or 16");
    expect_usage_error("--bit-depth nan", "--bit-depth: expected 8 or 16");
    EXPECT_EQ(file_count(), 2u);  // x.png and y.png
}

TEST_F(Cli, ExposureAndToneMapDevelopTheColour) {
    const std::string size = "--width 16 --height 12 -q ";
    ASSERT_EQ(run("render " + size + "-o " + path("plain.pfm")).status, 0);
    ASSERT_EQ(run("render " + size + "--exposure 1 -o " + path("bright.pfm")).status, 0);
    const Result floats =
        run("render " + size + "--exposure 1 --tonemap aces -o " + path("aces.pfm"));
    ASSERT_EQ(floats.status, 0) << floats.output;
    EXPECT_NE(floats.output.find("--tonemap is for pictures"), std::string::npos) << floats.output;
    const hikari::Image plain = hikari::read_image(path("plain.pfm")),
                        bright = hikari::read_image(path("bright.pfm")),
                        aces = hikari::read_image(path("aces.pfm"));
    for (size_t i = 0; i < plain.pixels.size(); ++i) {
        ASSERT_EQ(bright.pixels[i], 2.0f * plain.pixels[i]) << i;
        ASSERT_EQ(aces.pixels[i], bright.pixels[i]) << i << ": float files are never tone mapped";
    }
    // clamp is the default, byte for byte; reinhard changes the picture.
    ASSERT_EQ(run("render " + size + "-o " + path("a.png")).status, 0);
    ASSERT_EQ(run("render " + size + "--tonemap clamp --exposure 0 -o " + path("b.png")).status, 0);
    ASSERT_EQ(run("render " + size + "--tonemap reinhard -o " + path("c.png")).status, 0);
    EXPECT_EQ(hikari::testing::read_text(path("a.png")), hikari::testing::read_text(path("b.png")));
    EXPECT_NE(hikari::testing::read_text(path("a.png")), hikari::testing::read_text(path("c.png")));
    // AOV buffers are written as they are.
    ASSERT_EQ(run("render " + size + "--aov depth -o " + path("d.pfm")).status, 0);
    const Result depth = run("render " + size + "--aov depth --exposure 2 -o " + path("e.pfm"));
    ASSERT_EQ(depth.status, 0) << depth.output;
    EXPECT_NE(depth.output.find("--aov depth is written as is"), std::string::npos) << depth.output;
    EXPECT_EQ(hikari::testing::read_text(path("d.pfm")), hikari::testing::read_text(path("e.pfm")));
    expect_usage_error("--tonemap bogus", "--tonemap");
    expect_usage_error("--exposure lots", "--exposure");
    expect_usage_error("--exposure nan", "--exposure");
    EXPECT_FALSE(fs::exists(path("out.png")));
}

TEST_F(Cli, GalleryRendersTheLecturesFiguresOnAnyModel) {
    // A model of our own (a square pyramid), not the repository's teapot.
    write("pyramid.obj",
          "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nv 0 1.5 0\n"
          "f 1 2 3 4\nf 1 5 2\nf 2 5 3\nf 3 5 4\nf 4 5 1\n");
    const Result r =
        run("gallery --width 48 --model " + path("pyramid.obj") + " -o " + path("gallery"));
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string index = hikari::testing::read_text(path("gallery/index.html"));
    size_t images = 0;
    for (const auto& entry : fs::directory_iterator(path("gallery"))) {
        if (entry.path().extension() != ".png") continue;
        ++images;
        EXPECT_NE(index.find("\"" + entry.path().filename().string() + "\""), std::string::npos)
            << entry.path();
        EXPECT_GT(fs::file_size(entry.path()), 60u) << entry.path();
    }
    EXPECT_GE(images, 25u);
    for (const char* fig : {"Fig 4.1a", "Fig 4.3", "Fig 4.7", "Fig 4.9a", "Fig 4.9c", "Fig 4.14",
                            "Fig 4.24", "Fig 4.29", "Fig 4.39", "Fig 4.43", "Alg 4.1", "Alg 4.2"})
        EXPECT_NE(index.find(fig), std::string::npos) << fig;
    EXPECT_NE(index.find("hikari render scenes/model.json -m hiddenline"), std::string::npos);
    EXPECT_NE(index.find("triangles culled"), std::string::npos);
    EXPECT_NE(index.find("id buffers of scanline and zbuffer agree on"), std::string::npos);
    EXPECT_TRUE(fs::exists(path("gallery/scenes/model.json")));
    EXPECT_FALSE(fs::exists(path("gallery/data")));
}

TEST_F(Cli, GalleryMistakesExitOneAndMakeNothing) {
    const Result missing = run("gallery --model " + path("none.obj") + " -o " + path("g"));
    EXPECT_EQ(missing.status, 1);
    EXPECT_NE(missing.output.find("hikari: error: "), std::string::npos) << missing.output;
    EXPECT_FALSE(fs::exists(path("g")));
    write("file", "not a directory");
    const Result blocked = run("gallery --width 32 -o " + path("file/g"));
    EXPECT_EQ(blocked.status, 1);
    EXPECT_NE(blocked.output.find("cannot write into"), std::string::npos) << blocked.output;
    EXPECT_EQ(run("gallery --width 2").status, 2);
}

/// A small scene for the path tracer: a lamp over a floor, and a material that would create
/// light (kd + ks = 1.3).
constexpr const char* k_lamp_scene = R"({
  "camera": {"eye": [0, 1, 3], "look_at": [0, 0.5, 0], "fov_y": 50, "width": 24, "height": 16},
  "materials": {"lamp": {"emission": [4, 4, 4]}, "floor": {"kd": 0.8, "ks": 0.5}},
  "objects": [{"type": "sphere", "center": [0, 1.5, 0], "radius": 0.3, "material": "lamp"},
              {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"}]})";

TEST_F(Cli, PathTracesWithStatsAndWarnings) {
    write("lamp.json", k_lamp_scene);
    const Result r = run("render " + path("lamp.json") + " -m path --spp 4 --max-depth 3 --stats " +
                         "--filter gaussian --clamp 100 -o " + path("lamp.exr"));
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(fs::exists(path("lamp.exr")));
    EXPECT_NE(r.output.find("Mpaths/s"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("0 NaN/Inf samples"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("warning: material 'floor' would reflect more light"),
              std::string::npos)
        << r.output;
    const Image image = read_image(path("lamp.exr"));
    EXPECT_EQ(image.width, 24);
    // Without --spp, a time limit samples until the time is up; progressive snapshots rewrite
    // the output meanwhile and the final image replaces them.
    const Result timed = run("render " + path("lamp.json") + " -m path -q --time-limit 0.5 " +
                             "--progressive 0.1 -o " + path("timed.png"));
    EXPECT_EQ(timed.status, 0) << timed.output;
    EXPECT_TRUE(fs::exists(path("timed.png")));
    EXPECT_EQ(file_count(), 3U);  // the scene and two images: no temporary files left
}

TEST_F(Cli, PathOptionMistakesAreUsageErrors) {
    expect_usage_error("-m path --shadows ray", "--shadows is not an option of method path");
    expect_usage_error("-m raytrace --clamp 2", "--clamp is not an option of method raytrace");
    expect_usage_error("-m raytrace --max-depth 0", "--max-depth 0: raytrace needs");
    expect_usage_error("-m path --filter tent", "--filter: tent not in");
}

TEST_F(Cli, BenchB5RendersTheCornellBoxAsJson) {
    write("lamp.json", k_lamp_scene);
    const Result r = run("bench B5 --scene " + path("lamp.json") + " --reps 1 2>/dev/null");
    EXPECT_EQ(r.status, 0) << r.output;
    for (const char* key :
         {"\"bench\": \"B5\"", "\"threads\": 1", "\"ms\": ", "\"mean_srgb\": [", "\"spp\": 64"})
        EXPECT_NE(r.output.find(key), std::string::npos) << key << " in " << r.output;
    EXPECT_EQ(run("bench B5 --mesh " + path("lamp.json")).status, 1);
}

TEST_F(Cli, CompareReportsPsnrAndWritesADifferenceImage) {
    ASSERT_EQ(run("render --width 48 -o " + path("ray.png")).status, 0);
    ASSERT_EQ(run("render -m zbuffer --width 48 -o " + path("z.png")).status, 0);
    const Result r =
        run("compare " + path("ray.png") + " " + path("z.png") + " -o " + path("diff.png"));
    EXPECT_EQ(r.status, 0) << r.output;
    for (const char* key : {"PSNR ", " dB", "max difference ", "differing pixels "})
        EXPECT_NE(r.output.find(key), std::string::npos) << key << " in " << r.output;
    EXPECT_TRUE(fs::exists(path("diff.png")));
    const Result same = run("compare --psnr " + path("ray.png") + " " + path("ray.png"));
    EXPECT_EQ(same.output, "inf\n");
    // Different sizes, a missing file: input errors.
    ASSERT_EQ(run("render --width 32 -o " + path("small.png")).status, 0);
    EXPECT_EQ(run("compare " + path("ray.png") + " " + path("small.png")).status, 1);
    EXPECT_EQ(run("compare " + path("ray.png") + " " + path("none.png")).status, 1);
    EXPECT_EQ(run("compare " + path("ray.png")).status, 2);
}

TEST_F(Cli, DefaultOutputNamesKeepEveryMethodsPicture) {
    // Run in the test's directory, without -o: each method writes its own file.
    for (const char* method : {"raytrace", "zbuffer", "path"}) {
        const std::string command = "cd " + m_dir.string() + " && " + HIKARI_CLI_PATH +
                                    " render -q --width 16 --spp 1 -m " + method;
        EXPECT_EQ(std::system(command.c_str()), 0) << command;
    }
    EXPECT_TRUE(fs::exists(path("assignment.png")));
    EXPECT_TRUE(fs::exists(path("assignment-zbuffer.png")));
    EXPECT_TRUE(fs::exists(path("assignment-path.png")));
}

}  // namespace
}  // namespace hikari

namespace {

using hikari::Image;
using hikari::read_image;

const std::string k_two_spheres = R"({
  "camera": {"eye": [0, 0, 6], "fov_y": 40, "width": 40, "height": 30},
  "ambient": 0.2,
  "materials": {"clay": {"ka": [0.3, 0.2, 0.1], "kd": [0.8, 0.5, 0.3], "ks": 0.4, "shininess": 20}},
  "lights": [{"type": "point", "position": [4, 4, 6], "intensity": 60}],
  "objects": [{"type": "sphere", "center": [-0.8, 0, 0], "radius": 0.7, "material": "clay"},
              {"type": "sphere", "center": [0.9, 0, -1], "radius": 0.7, "material": "clay"}]
})";

TEST_F(Cli, SetGivesTheImageOfTheEditedScene) {
    write("scene.json", k_two_spheres);
    std::string edited = k_two_spheres;
    edited.replace(edited.find("\"shininess\": 20"), 15, "\"shininess\": 5");
    edited.replace(edited.find("\"fov_y\": 40"), 11, "\"fov_y\": 30");
    write("edited.json", edited);
    ASSERT_EQ(run("render " + path("scene.json") +
                  " --set materials.clay.shininess=5 --set camera.fov_y=30 -o " + path("set.pfm"))
                  .status,
              0);
    ASSERT_EQ(run("render " + path("edited.json") + " -o " + path("edited.pfm")).status, 0);
    EXPECT_EQ(read_image(path("set.pfm")).pixels, read_image(path("edited.pfm")).pixels);
}

TEST_F(Cli, SetErrorsNameThePath) {
    write("scene.json", k_two_spheres);
    const Result bad = run("render " + path("scene.json") +
                           " --set materials.clay.shininess=-5 -o " + path("out.png"));
    EXPECT_EQ(bad.status, 1) << bad.output;
    EXPECT_NE(bad.output.find("materials.clay.shininess"), std::string::npos) << bad.output;
    const Result range =
        run("render " + path("scene.json") + " --set objects[7].radius=1 -o " + path("out.png"));
    EXPECT_EQ(range.status, 1) << range.output;
    EXPECT_NE(range.output.find("objects: has 2 elements"), std::string::npos) << range.output;
    expect_usage_error("--set camera.fov_y", "--set camera.fov_y: expected PATH=VALUE");
    EXPECT_FALSE(fs::exists(path("out.png")));
}

TEST_F(Cli, ShadingTermsSumToColour) {
    write("scene.json", k_two_spheres);
    for (const char* aov : {"color", "ambient", "diffuse", "specular"})
        ASSERT_EQ(run("render " + path("scene.json") + " -m zbuffer --aov " + aov + " -o " +
                      path(std::string(aov) + ".pfm"))
                      .status,
                  0)
            << aov;
    const Image c = read_image(path("color.pfm")), a = read_image(path("ambient.pfm")),
                d = read_image(path("diffuse.pfm")), s = read_image(path("specular.pfm"));
    for (size_t i = 0; i < c.pixels.size(); ++i)
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(a.pixels[i][k] + d.pixels[i][k] + s.pixels[i][k], c.pixels[i][k], 1e-5f);
    expect_usage_error(path("scene.json") + " -m path --aov diffuse",
                       "--aov diffuse: method path does not shade by");
}

TEST_F(Cli, DepthPngSpansTheGreyRange) {
    write("scene.json", k_two_spheres);
    ASSERT_EQ(run("render " + path("scene.json") + " --aov depth -o " + path("d.png")).status, 0);
    const Image d = read_image(path("d.png"));
    float lo = 1.0f, hi = 0.0f;
    for (const hikari::Vec3& p : d.pixels) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
    EXPECT_EQ(lo, 0.0f);
    EXPECT_EQ(hi, 1.0f);
    expect_usage_error(path("scene.json") + " --depth-range 1,5",
                       "--depth-range is for --aov depth");
    expect_usage_error(path("scene.json") + " --aov depth --depth-range 5,1",
                       "--depth-range: FAR must be greater than NEAR");
}

TEST_F(Cli, SeveralMethodsInOneRun) {
    write("scene.json", k_two_spheres);
    const Result r =
        run("render " + path("scene.json") + " -m zbuffer,scanline,raytrace -o " + path("o.png"));
    ASSERT_EQ(r.status, 0) << r.output;
    for (const char* method : {"zbuffer", "scanline", "raytrace"})
        EXPECT_TRUE(fs::exists(path(std::string("o-") + method + ".png"))) << method;
    EXPECT_FALSE(fs::exists(path("o.png")));
    // An option one of them ignores is a warning; one that none takes, an error.
    const Result spp =
        run("render " + path("scene.json") + " -m zbuffer,path --spp 2 -o " + path("w.png"));
    EXPECT_EQ(spp.status, 0) << spp.output;
    const Result shadows = run("render " + path("scene.json") +
                               " -m zbuffer,raytrace --interp flat -o " + path("w.png"));
    EXPECT_EQ(shadows.status, 0) << shadows.output;
    EXPECT_NE(shadows.output.find("hikari: warning: --interp is not an option of raytrace"),
              std::string::npos)
        << shadows.output;
    expect_usage_error(path("scene.json") + " -m zbuffer,scanline --filter gaussian",
                       "--filter is not an option of any method asked for");
    expect_usage_error(path("scene.json") + " -m zbuffer,zbuffer",
                       "-m: method zbuffer is named twice");
}

TEST_F(Cli, SeveralMethodsWithoutOutputNameEachImage) {
    write("scene.json", k_two_spheres);
    const std::string cd = "cd " + m_dir.string() + " && ";
    const std::string command =
        cd + std::string(HIKARI_CLI_PATH) + " render scene.json -m raytrace,zbuffer -q 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0);
    EXPECT_TRUE(fs::exists(path("scene-raytrace.png")));
    EXPECT_TRUE(fs::exists(path("scene-zbuffer.png")));
}

}  // namespace

namespace {

TEST_F(Cli, ExplainPrintsOneStepOfTheAlgorithm) {
    write("scene.json", k_two_spheres);
    const Result z = run("explain " + path("scene.json") + " -m zbuffer --pixel 12,15");
    EXPECT_EQ(z.status, 0) << z.output;
    EXPECT_NE(z.output.find("Z-buffer (Alg 4.2) at pixel (12, 15)"), std::string::npos) << z.output;
    EXPECT_NE(z.output.find("sphere (primitive 0)"), std::string::npos) << z.output;
    const Result s = run("explain " + path("scene.json") + " -m scanline --row 15");
    EXPECT_EQ(s.status, 0) << s.output;
    EXPECT_NE(s.output.find("Active edge list at y = 15.5"), std::string::npos) << s.output;
    const Result missing = run("explain " + path("scene.json") + " -m scanline");
    EXPECT_EQ(missing.status, 1);
    EXPECT_NE(missing.output.find("needs --row Y"), std::string::npos) << missing.output;
    const Result outside = run("explain " + path("scene.json") + " -m zbuffer --pixel 99,1");
    EXPECT_EQ(outside.status, 1);
    EXPECT_NE(outside.output.find("outside the 40x30 image"), std::string::npos) << outside.output;
    EXPECT_EQ(run("explain " + path("scene.json") + " -m path --row 1").status, 2);
}

TEST_F(Cli, PrintMatricesShowsTheTransformsAndRenders) {
    write("scene.json", k_two_spheres);
    const Result r =
        run("render " + path("scene.json") + " --print-matrices -q -o " + path("m.png"));
    EXPECT_EQ(r.status, 0) << r.output;
    for (const char* text : {"p_s = V P M p_w", "M (model-view", "P (perspective projection",
                             "V (viewport", "P M p_w", "pixels"})
        EXPECT_NE(r.output.find(text), std::string::npos) << text << "\n" << r.output;
    EXPECT_TRUE(fs::exists(path("m.png")));
}

}  // namespace

namespace {

TEST_F(Cli, AlgorithmAovsForTheirMethodsOnly) {
    write("scene.json", k_two_spheres);
    const Result r = run("render " + path("scene.json") + " -m depthsort --aov paint-order -o " +
                         path("order.png"));
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("hikari: paint-order:"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::exists(path("order.png")));
    expect_usage_error(path("scene.json") + " -m zbuffer --aov paint-order",
                       "--aov paint-order shows the work of depthsort, not of method zbuffer");
    expect_usage_error(path("scene.json") + " -m raytrace --aov overdraw",
                       "--aov overdraw shows the work of zbuffer, depthsort");
}

}  // namespace

namespace {

TEST_F(Cli, RasterStatsCountTheStages) {
    write("scene.json", k_two_spheres);
    const Result z =
        run("render " + path("scene.json") +
            " -m zbuffer --tessellation 16 --cull back --stats -q -o " + path("z.png"));
    EXPECT_EQ(z.status, 0) << z.output;
    EXPECT_NE(z.output.find("triangles in"), std::string::npos) << z.output;
    EXPECT_NE(z.output.find("fragments depth-tested"), std::string::npos) << z.output;
    EXPECT_EQ(z.output.find(" 0 culled"), std::string::npos) << "spheres have back faces\n"
                                                             << z.output;
    const Result d =
        run("render " + path("scene.json") + " -m depthsort --stats -q -o " + path("d.png"));
    EXPECT_NE(d.output.find("depth-sort splits"), std::string::npos) << d.output;
}

}  // namespace

namespace {

TEST_F(Cli, MethodsSayWhatTheyLeaveOut) {
    std::string mirror = k_two_spheres;
    mirror.replace(mirror.find("\"shininess\": 20"), 15,
                   "\"shininess\": 20, \"reflectivity\": 0.5");
    write("mirror.json", mirror);
    const Result z = run("render " + path("mirror.json") + " -m zbuffer -q -o " + path("z.png"));
    EXPECT_EQ(z.status, 0) << z.output;
    EXPECT_NE(z.output.find("hikari: warning: material 'clay': reflectivity and transparency"),
              std::string::npos)
        << z.output;
    const Result r = run("render " + path("mirror.json") + " -q -o " + path("r.png"));
    EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
}

TEST_F(Cli, WireframeOverlayDrawsOverTheImage) {
    write("scene.json", k_two_spheres);
    ASSERT_EQ(run("render " + path("scene.json") + " -m zbuffer --tessellation 8 -q -o " +
                  path("plain.pfm"))
                  .status,
              0);
    const Result r = run("render " + path("scene.json") +
                         " -m zbuffer --tessellation 8 --wireframe-overlay -q -o " + path("w.pfm"));
    ASSERT_EQ(r.status, 0) << r.output;
    const Image plain = read_image(path("plain.pfm")), lined = read_image(path("w.pfm"));
    int darker = 0;
    for (size_t i = 0; i < plain.pixels.size(); ++i)
        darker += lined.pixels[i].x < plain.pixels[i].x - 0.05f;
    EXPECT_GT(darker, 20);
    expect_usage_error(path("scene.json") + " -m wireframe --wireframe-overlay",
                       "--wireframe-overlay draws over a shaded image");
}

}  // namespace

namespace {

TEST_F(Cli, ExplainRaytraceAndDepthSort) {
    write("scene.json", k_two_spheres);
    const Result r = run("explain " + path("scene.json") + " -m raytrace --pixel 12,15");
    EXPECT_EQ(r.status, 0) << r.output;
    for (const char* text :
         {"#0 camera ray", "hits sphere (primitive 0)", "shadow ray to light 0", "Pixel colour"})
        EXPECT_NE(r.output.find(text), std::string::npos) << text << "\n" << r.output;
    const Result d = run("explain " + path("scene.json") + " -m depthsort --width 16");
    EXPECT_EQ(d.status, 0) << d.output;
    EXPECT_NE(d.output.find("Painting order"), std::string::npos) << d.output;
}

TEST_F(Cli, ModelFilesRenderDirectly) {
    const std::string models = std::string(HIKARI_SOURCE_DIR) + "/scenes/models/";
    for (const char* model : {"BoxTextured.glb", "BoxTextured.gltf", "Wuson.ply", "teapot.obj"}) {
        const Result r = run("render " + models + model + " --width 48 --ground -o " +
                             path(std::string(model) + ".png"));
        EXPECT_EQ(r.status, 0) << model << ": " << r.output;
        EXPECT_TRUE(fs::exists(path(std::string(model) + ".png"))) << model;
        EXPECT_NE(r.output.find("triangles"), std::string::npos) << r.output;  // the summary
    }
    // The camera options move the framing: a render from elsewhere differs.
    const Result moved = run("render " + models + "teapot.obj --width 48 --camera-from 0,9,0.1 " +
                             "--look-at 0,1,0 -m zbuffer -o " + path("top.pfm"));
    EXPECT_EQ(moved.status, 0) << moved.output;
    const Result framed =
        run("render " + models + "teapot.obj --width 48 -m zbuffer -o " + path("framed.pfm"));
    EXPECT_EQ(framed.status, 0) << framed.output;
    EXPECT_NE(hikari::testing::read_text(path("top.pfm")),
              hikari::testing::read_text(path("framed.pfm")));
    expect_usage_error(models + "teapot.obj --crease-angle 200", "--crease-angle");
}

TEST_F(Cli, BrokenModelFilesAreOneErrorLineAndNoImage) {
    write("short.ply",
          "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
          "property float x\nproperty float y\nproperty float z\nelement face 1\n"
          "property list uchar int vertex_indices\nend_header\n\x01\x02");
    write("huge.ply",
          "ply\nformat ascii 1.0\nelement vertex 1000000000000\n"
          "property float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n");
    write("nobin.gltf", R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "missing.bin",
        "byteLength": 36}], "bufferViews": [{"buffer": 0, "byteLength": 36}], "accessors":
        [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}], "meshes":
        [{"primitives": [{"attributes": {"POSITION": 0}}]}], "nodes": [{"mesh": 0}]})");
    write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
    for (const char* name : {"short.ply", "huge.ply", "nobin.gltf", "range.obj"}) {
        const Result r = run("render " + path(name) + " -o " + path("out.png"));
        EXPECT_EQ(r.status, 1) << name << ": " << r.output;
        EXPECT_EQ(r.output.rfind("hikari: error: ", 0), 0u) << r.output;
        EXPECT_NE(r.output.find(name), std::string::npos) << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
        EXPECT_FALSE(fs::exists(path("out.png"))) << name;
    }
    const Result info = run("info " + path("huge.ply"));
    EXPECT_EQ(info.status, 1) << info.output;
}

TEST_F(Cli, InfoSaysWhatAFileHolds) {
    const Result ply = run("info " + std::string(HIKARI_SOURCE_DIR) + "/scenes/models/Wuson.ply");
    EXPECT_EQ(ply.status, 0) << ply.output;
    EXPECT_NE(ply.output.find("triangles   3732"), std::string::npos) << ply.output;
    EXPECT_NE(ply.output.find("loaded in"), std::string::npos) << ply.output;
    const Result glb =
        run("info " + std::string(HIKARI_SOURCE_DIR) + "/scenes/models/BoxTextured.glb");
    EXPECT_NE(glb.output.find("textures    1"), std::string::npos) << glb.output;
    const Result scene = run("info " + std::string(HIKARI_SOURCE_DIR) + "/scenes/whitted.json");
    EXPECT_EQ(scene.status, 0) << scene.output;
    EXPECT_NE(scene.output.find("spheres"), std::string::npos) << scene.output;
}

TEST_F(Cli, VertexColoursShadeInEveryMethod) {
    // A quad, red on its left edge and green on its right (8-bit PLY colours), rendered as a
    // model: every method must show red on the left half and green on the right, alike.
    write("quad.ply",
          "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
          "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
          "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
          "-1 -1 0 255 0 0\n1 -1 0 0 255 0\n1 1 0 0 255 0\n-1 1 0 255 0 0\n4 0 1 2 3\n");
    std::vector<hikari::Image> images;
    for (const char* method : {"raytrace", "zbuffer", "scanline", "path --spp 4"}) {
        const std::string out = path(std::string(method).substr(0, 4) + ".pfm");
        const Result r =
            run("render " + path("quad.ply") + " --width 64 -m " + method + " -o " + out);
        ASSERT_EQ(r.status, 0) << method << ": " << r.output;
        const hikari::Image image = hikari::read_image(out);
        double left = 0, right = 0;  // red minus green over the quad (no blue in it)
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                const hikari::Vec3 c = image.at(x, y);
                if (c.z < 0.05f) (x < image.width / 2 ? left : right) += c.x - c.y;
            }
        EXPECT_GT(left, 0.0) << method;
        EXPECT_LT(right, 0.0) << method;
        images.push_back(image);
    }
    // The Z-buffer and the scanline method shade as the ray tracer does (at most a few pixels
    // on the silhouette may differ, where a pixel centre lies on an edge).
    for (size_t k = 1; k < 3; ++k) {
        size_t differ = 0;
        for (size_t i = 0; i < images[0].pixels.size(); ++i)
            differ += length(images[0].pixels[i] - images[k].pixels[i]) > 0.02f;
        EXPECT_LE(differ, images[0].pixels.size() / 100) << k;
    }
}

}  // namespace
