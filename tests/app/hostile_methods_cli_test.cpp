// Hostile inputs through the hikari program (issue 41), the methods' side: every large buffer a
// method makes is counted against --max-memory before it is made (one line, exit 1, peak memory
// under the limit), textures are protected inputs, output paths are checked before any work, and
// workbook temporaries live beside their output.

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../io/temp_dir.h"

#include "run_hikari.h"

extern char** environ;

namespace {

namespace fs = std::filesystem;

using Result = hikari::testing::RunResult;
using hikari::testing::run_hikari;

/// What `hikari ARGS` printed and exited with, and the most memory it held (its peak resident
/// set, from getrusage of a process whose only children are the shell and hikari).
struct Measured {
    Result result;
    double peak_mib = 0;
};

Measured run_measured(const std::string& args) {
    int pipe_fds[2];
    if (::pipe(pipe_fds) != 0) return {};
    const pid_t child = ::fork();
    if (child == 0) {
        ::close(pipe_fds[0]);
        const Result r = run_hikari(args);
        rusage usage{};
        ::getrusage(RUSAGE_CHILDREN, &usage);
        const std::string report =
            std::to_string(r.status) + " " + std::to_string(usage.ru_maxrss) + "\n" + r.output;
        [[maybe_unused]] const ssize_t n = ::write(pipe_fds[1], report.data(), report.size());
        ::_exit(0);
    }
    ::close(pipe_fds[1]);
    std::string report;
    char buffer[4096];
    for (ssize_t n; (n = ::read(pipe_fds[0], buffer, sizeof buffer)) > 0;) report.append(buffer, n);
    ::close(pipe_fds[0]);
    ::waitpid(child, nullptr, 0);
    Measured m;
    long kib = 0;
    int status = -1;
    if (std::sscanf(report.c_str(), "%d %ld", &status, &kib) != 2) return m;
    m.result = {status, report.substr(report.find('\n') + 1)};
    m.peak_mib = static_cast<double>(kib) / 1024.0;
    return m;
}

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define HIKARI_TEST_UNDER_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define HIKARI_TEST_UNDER_ASAN 1
#endif

/// The most a refusing `hikari` may hold, in MiB, under a --max-memory of `gib`: the limit plus
/// the program's own 150 MB (code, libraries, the scene). Under AddressSanitizer every block also
/// carries an eighth in shadow memory, and freed blocks stay resident in its 256 MB quarantine.
double allowed_peak_mib(double gib) {
#ifdef HIKARI_TEST_UNDER_ASAN
    return gib * 1024 * 1.125 + 150 + 256;
#else
    return gib * 1024 + 150;
#endif
}

class HostileMethods : public ::testing::Test {
  protected:
    std::string path(const std::string& name) const { return (m_dir / name).string(); }
    void write(const std::string& name, const std::string& bytes) const {
        hikari::testing::write_text(m_dir / name, bytes);
    }
    /// `hikari render ARGS --max-memory GIB -o out.png` refuses with exit 1 and one line that
    /// names `what`, stays under the limit plus the program's own 150 MB, and writes nothing.
    void expect_refused_under(const std::string& args, double gib, const std::string& what) {
        const Measured m = run_measured("render -q " + args + " --max-memory " +
                                        std::to_string(gib) + " -o " + path("out.png"));
        EXPECT_EQ(m.result.status, 1) << args << ": " << m.result.output;
        EXPECT_EQ(m.result.output.rfind("hikari: error: ", 0), 0u) << m.result.output;
        EXPECT_NE(m.result.output.find(what), std::string::npos) << m.result.output;
        EXPECT_NE(m.result.output.find("(raise it with --max-memory "), std::string::npos)
            << m.result.output;
        EXPECT_EQ(std::count(m.result.output.begin(), m.result.output.end(), '\n'), 1)
            << m.result.output;
        EXPECT_LT(m.peak_mib, allowed_peak_mib(gib)) << args;
        EXPECT_FALSE(fs::exists(path("out.png")));
    }

    hikari::testing::TempDir m_dir;
};

const std::string k_sphere_scene = R"({
  "camera": {"eye": [0, 0, 4], "look_at": [0, 0, 0], "width": 32, "height": 24},
  "lights": [LIGHTS],
  "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]
})";

std::string sphere_scene(const std::string& lights) {
    std::string s = k_sphere_scene;
    s.replace(s.find("LIGHTS"), 6, lights);
    return s;
}

TEST_F(HostileMethods, PointLightCubeMapsAreCountedBeforeTheyAreDrawn) {
    std::string lights;
    for (int i = 0; i < 30; ++i)
        lights += std::string(i ? ", " : "") + R"({"type": "point", "position": [)" +
                  std::to_string(i % 5 - 2) + ", 3, " + std::to_string(i / 5) +
                  R"(], "intensity": [0.1, 0.1, 0.1]})";
    write("lights.json", sphere_scene(lights));
    expect_refused_under(path("lights.json") + " -m zbuffer", 0.5, "180 shadow map faces");
    write("two.json",
          sphere_scene(R"({"type": "point", "position": [0, 3, 0], "intensity": [1, 1, 1]},
                                      {"type": "point", "position": [2, 3, 0], "intensity": [1, 1, 1]})"));
    expect_refused_under(path("two.json") + " -m zbuffer --shadow-map-size 8192", 0.5,
                         "12 shadow map faces of 8192x8192 texels");
    // The same scene at the default size renders.
    EXPECT_EQ(run_hikari("render -q " + path("two.json") + " -m zbuffer --max-memory 0.5 -o " +
                         path("ok.png"))
                  .status,
              0);
}

TEST_F(HostileMethods, SphereTessellationIsCountedBeforeItIsMade) {
    write("s.json",
          sphere_scene(
              R"({"type": "directional", "direction": [0, -1, -1], "intensity": [1, 1, 1]})"));
    for (const char* method : {"zbuffer", "hiddenline", "depthsort"})
        expect_refused_under(path("s.json") + " -m " + method + " --tessellation 4096", 0.25,
                             "--tessellation");
}

TEST_F(HostileMethods, OneMeshRepeatedHundredsOfTimesIsCountedInTheRasterPipeline) {
    std::string obj = "v 0 0 0\n";
    for (int i = 0; i < 60; ++i)
        for (int j = 0; j < 60; ++j)
            obj += "v " + std::to_string(i) + " " + std::to_string(j) + " 1\n";
    for (int i = 0; i + 1 < 60; ++i)
        for (int j = 0; j + 1 < 60; ++j) {
            const int a = 2 + i * 60 + j;
            obj += "f " + std::to_string(a) + " " + std::to_string(a + 1) + " " +
                   std::to_string(a + 60) + "\n";
        }
    write("grid.obj", obj);
    std::string objects;
    for (int k = 0; k < 300; ++k)
        objects += std::string(k ? ", " : "") + R"({"type": "mesh", "file": "grid.obj"})";
    write("many.json", R"({"camera": {"eye": [30, 30, 120], "look_at": [30, 30, 0],
                           "width": 32, "height": 24}, "objects": [)" +
                           objects + "]}");
    expect_refused_under(path("many.json") + " -m zbuffer --shadows none", 0.25,
                         "rasterizing 1044300 triangles");
}

// Camera between a mirror, a glass pane and a second mirror: each glass hit spawns a mirror and a
// refracted ray that both come back, so the tree doubles every two levels.
const std::string k_ray_tree_scene = R"({
  "camera": {"eye": [0, 0, 0], "look_at": [0, 0, -1], "width": 1, "height": 1},
  "materials": {"mirror": {"kd": [0, 0, 0], "reflectivity": 0.9},
                "glass": {"kd": [0, 0, 0], "reflectivity": 0.5, "transparency": 0.5,
                          "ior": 1.5}},
  "lights": [{"type": "point", "position": [0, 0, 0], "intensity": [1, 1, 1]}],
  "objects": [
    {"type": "plane", "point": [0, 0, -1], "normal": [0, 0, 1], "material": "mirror"},
    {"type": "plane", "point": [0, 0, 0.5], "normal": [0, 0, 1], "material": "glass"},
    {"type": "plane", "point": [0, 0, 2], "normal": [0, 0, -1], "material": "mirror"}]})";

TEST_F(HostileMethods, TheRayTreeBetweenMirrorAndGlassIsCheckedLevelByLevel) {
    write("tree.json", k_ray_tree_scene);
    // Many pixels: the trees of all of them reach the memory limit first.
    expect_refused_under(path("tree.json") + " --width 32 --height 24 --max-depth 48", 0.25,
                         "the ray tree");
    // A shallow tree renders.
    EXPECT_EQ(run_hikari("render -q " + path("tree.json") + " --max-depth 12 --max-memory 0.25 " +
                         "-o " + path("ok.png"))
                  .status,
              0);
}

TEST_F(HostileMethods, TheRayTreeOfOnePixelIsRefusedWhereItsBreadthExplodes) {
    // One pixel under any limit (the default one included): refused at the level where the
    // tree holds 65536 rays per camera ray, long before it fills the memory; in explain too.
    write("tree.json", k_ray_tree_scene);
    for (const std::string& command :
         {"render -q " + path("tree.json") + " --max-depth 64 -o " + path("out.png"),
          "explain -m raytrace --pixel 0,0 --max-depth 48 " + path("tree.json")}) {
        const Measured m = run_measured(command);
        EXPECT_EQ(m.result.status, 1) << m.result.output;
        EXPECT_EQ(m.result.output.rfind("hikari: error: the ray tree grows past 65536 rays per "
                                        "camera ray at level 35 of --max-depth ",
                                        0),
                  0u)
            << m.result.output;
        EXPECT_EQ(std::count(m.result.output.begin(), m.result.output.end(), '\n'), 1);
        EXPECT_LT(m.peak_mib, allowed_peak_mib(0.25));
    }
    EXPECT_FALSE(fs::exists(path("out.png")));
}

TEST_F(HostileMethods, ExplainCompareAndInfoTakeTheMemoryLimit) {
    write("tree.json", k_ray_tree_scene);
    // explain records every ray of the tree: 2^15 rays at level 30 need more than 8 MiB.
    const Result e = run_hikari("explain -m raytrace --pixel 0,0 --max-depth 30 --max-memory " +
                                std::to_string(8.0 / 1024) + " " + path("tree.json"));
    EXPECT_EQ(e.status, 1) << e.output;
    EXPECT_NE(e.output.find("the ray tree"), std::string::npos) << e.output;
    EXPECT_NE(e.output.find("(raise it with --max-memory "), std::string::npos) << e.output;
    // compare: two 1024x1024 images, 12 MiB each decoded, under 16 MiB together.
    const std::string big = path("big.pfm");
    ASSERT_EQ(run_hikari("render -q --width 1024 --height 1024 -o " + big).status, 0);
    const Result c =
        run_hikari("compare --max-memory " + std::to_string(16.0 / 1024) + " " + big + " " + big);
    EXPECT_EQ(c.status, 1) << c.output;
    EXPECT_NE(c.output.find("(raise it with --max-memory "), std::string::npos) << c.output;
    // info reads the model under the limit.
    const Result i =
        run_hikari("info --max-memory " + std::to_string(1.0 / (1 << 20)) + " " +
                   (fs::path(HIKARI_SOURCE_DIR) / "scenes/models/teapot.obj").string());
    EXPECT_EQ(i.status, 1) << i.output;
    EXPECT_NE(i.output.find("(raise it with --max-memory "), std::string::npos) << i.output;
}

TEST_F(HostileMethods, TexturesTheRenderReadsAreNeverOverwritten) {
    write("tex.png", "not really a picture, but named by the MTL");
    write("m.mtl", "newmtl a\nKd 1 1 1\nmap_Kd -s 1 1 1 tex.png\n");
    write("m.obj", "mtllib m.mtl\nusemtl a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    write("s.json", R"({"objects": [{"type": "mesh", "file": "m.obj"}]})");
    for (const std::string& input : {path("m.obj"), path("s.json")}) {
        const Result r = run_hikari("render -q " + input + " -o " + path("tex.png"));
        EXPECT_EQ(r.status, 2) << r.output;
        EXPECT_NE(r.output.find("refusing to overwrite a file the model reads"), std::string::npos)
            << r.output;
        EXPECT_EQ(hikari::testing::read_text(m_dir / "tex.png"),
                  "not really a picture, but named by the MTL");
    }
    const Result mtl = run_hikari("render -q " + path("m.obj") + " -o " + path("m.mtl"));
    EXPECT_EQ(mtl.status, 2) << mtl.output;
    // A glTF's external image.
    const fs::path models = fs::path(HIKARI_SOURCE_DIR) / "scenes" / "models";
    fs::copy_file(models / "BoxTextured.gltf", m_dir / "BoxTextured.gltf");
    fs::copy_file(models / "BoxTextured0.bin", m_dir / "BoxTextured0.bin");
    fs::copy_file(models / "CesiumLogoFlat.png", m_dir / "CesiumLogoFlat.png");
    const auto size = fs::file_size(m_dir / "CesiumLogoFlat.png");
    const Result g =
        run_hikari("render -q " + path("BoxTextured.gltf") + " -o " + path("CesiumLogoFlat.png"));
    EXPECT_EQ(g.status, 2) << g.output;
    EXPECT_EQ(fs::file_size(m_dir / "CesiumLogoFlat.png"), size);
}

TEST_F(HostileMethods, OutputPathsAreCheckedBeforeAnyWork) {
    // A path longer than the system allows, through directories that exist.
    std::string long_dir = m_dir.path().string();
    while (long_dir.size() < 4078 - 8) long_dir += "/.";
    const Result r =
        run_hikari("render -q --tessellation 4096 -m hiddenline -o " + long_dir + "/x.png");
    EXPECT_EQ(r.status, 2) << r.output.substr(0, 300);
    EXPECT_NE(r.output.find("bytes long"), std::string::npos) << r.output.substr(0, 300);
    // compare -o d.svg is refused before the images are read (they do not even exist).
    const Result c = run_hikari("compare " + path("missing-a.png") + " " + path("missing-b.png") +
                                " -o " + path("d.svg"));
    EXPECT_EQ(c.status, 2) << c.output;
    EXPECT_FALSE(fs::exists(path("d.svg")));
}

TEST_F(HostileMethods, WorkbookTemporariesLiveBesideTheirOutput) {
    // No temporary folder at all: the workbook is written beside its output and leaves nothing.
    const char* saved = std::getenv("TMPDIR");
    const std::string tmpdir = saved ? saved : "";
    ::setenv("TMPDIR", path("no-such-dir").c_str(), 1);
    const Result r = run_hikari("render -q --width 8 --height 6 -o " + path("x.xlsx"));
    if (saved)
        ::setenv("TMPDIR", tmpdir.c_str(), 1);
    else
        ::unsetenv("TMPDIR");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(fs::exists(path("x.xlsx")));
    size_t entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(m_dir.path())) ++entries;
    EXPECT_EQ(entries, 1u);
}

/// Every file under `dir` with its size (hidden temporaries included).
std::map<std::string, uintmax_t> files_under(const fs::path& dir) {
    std::map<std::string, uintmax_t> files;
    std::error_code ec;
    for (const auto& e : fs::recursive_directory_iterator(dir, ec))
        if (e.is_regular_file()) files[e.path().string()] = e.file_size();
    return files;
}

TEST_F(HostileMethods, GalleryStopsItsRendersOnASignalAndLeavesNothingBehind) {
    for (const int sig : {SIGTERM, SIGINT}) {
        const std::string out = path("gallery-" + std::to_string(sig));
        const std::string program = HIKARI_CLI_PATH;
        std::vector<std::string> args = {program, "gallery", "--width", "320", "-o", out};
        std::vector<char*> argv;
        for (std::string& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
        pid_t pid = 0;
        ASSERT_EQ(posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ), 0);
        posix_spawn_file_actions_destroy(&actions);
        // Signal it while it renders: once its first figure has been written.
        for (int k = 0; k < 400 && files_under(out).size() < 3; ++k) ::usleep(25'000);
        ::kill(pid, sig);
        int status = 0;
        ASSERT_EQ(::waitpid(pid, &status, 0), pid);
        EXPECT_TRUE(WIFEXITED(status)) << sig;
        EXPECT_EQ(WEXITSTATUS(status), 128 + sig);
        // Nothing goes on writing after it has gone, and no temporary is left.
        const auto at_exit = files_under(out);
        ::sleep(3);
        EXPECT_EQ(files_under(out), at_exit) << sig;
        for (const auto& [file, size] : at_exit)
            EXPECT_EQ(file.find(".hikari-"), std::string::npos) << file;
    }
}

}  // namespace
