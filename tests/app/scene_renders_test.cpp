// Pins the renders of every scene in scenes/ with every method: a checksum of each output file,
// so that a refactoring that should change no pixel is seen to change none. A deliberate change
// of an image updates its line below (print the table with HIKARI_PRINT_CHECKSUMS=1).

#include <sys/wait.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../io/temp_dir.h"

namespace {

/// FNV-1a, 64 bits: enough to tell two renders apart.
uint64_t fnv1a(const std::string& bytes) {
    uint64_t h = 14695981039346656037ull;
    for (const unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
    return h;
}

/// One render: the scene, the command-line options, the output's extension.
struct Case {
    std::string scene;
    std::string options;
    std::string extension;
};

std::vector<Case> cases() {
    const std::vector<std::string> scenes = {"assignment",
                                             "assignment-1-hit-miss",
                                             "assignment-2-diffuse",
                                             "assignment-3-specular",
                                             "bunny",
                                             "teapot",
                                             "whitted",
                                             "bench/whitted",
                                             "depth-sort-centroid",
                                             "depth-sort-cyclic",
                                             "depth-sort-piercing"};
    const std::vector<std::string> methods = {"raytrace", "zbuffer", "scanline", "depthsort",
                                              "depthsort-naive"};
    std::vector<Case> all;
    for (const std::string& scene : scenes) {
        // The raster methods without shadows: the pictures from before they had any.
        for (const std::string& method : methods)
            all.push_back(
                {scene,
                 "-m " + method + " --width 64" + (method == "raytrace" ? "" : " --shadows none"),
                 "pfm"});
        // The ray tracer's 8-bit output path, its AOVs and its jittered samples.
        all.push_back({scene, "--width 64", "png"});
        all.push_back({scene, "--width 64 --aov id", "pfm"});
        all.push_back({scene, "--width 48 --spp 4", "pfm"});
        // The path tracer (the same scenes, lit the physical way; their lights have no size,
        // so light sampling finds them all).
        all.push_back({scene, "-m path --width 32 --spp 4", "pfm"});
    }
    all.push_back({"bench/cornell", "-m path --width 32 --spp 8", "pfm"});
    all.push_back({"cornell-glass", "-m path --width 32 --spp 8", "pfm"});
    all.push_back(
        {"bunny", "-m zbuffer --width 64 --interp gouraud --cull back --shadows none", "pfm"});
    all.push_back({"teapot", "-m scanline --width 64 --interp flat --shadows none", "pfm"});
    // Shadows: maps and volumes in the raster methods, none in the ray tracer.
    all.push_back({"bunny", "-m zbuffer --width 64 --shadow-map-size 256", "pfm"});
    all.push_back({"whitted", "-m scanline --width 64 --shadows volume", "pfm"});
    all.push_back({"teapot", "-m depthsort --width 64 --shadows volume --interp gouraud", "pfm"});
    all.push_back({"whitted", "--width 64 --shadows none", "pfm"});
    // The line methods, as images and as vectors.
    all.push_back({"teapot", "-m wireframe --width 64", "pfm"});
    all.push_back({"teapot", "-m hiddenline --width 64 --cull back --line-width 0.5", "pfm"});
    all.push_back({"lines-piercing", "-m hiddenline --width 96", "svg"});
    return all;
}

/// The checksums of cases(), in order.
const std::map<std::string, uint64_t>& pinned() {
    static const std::map<std::string, uint64_t> table = {
#include "scene_renders_checksums.inc"
    };
    return table;
}

std::string key(const Case& c) { return c.scene + " " + c.options + " ." + c.extension; }

TEST(SceneRenders, EveryRenderMatchesItsPinnedChecksum) {
    const hikari::testing::TempDir dir;
    const bool print = std::getenv("HIKARI_PRINT_CHECKSUMS") != nullptr;
    int index = 0;
    for (const Case& c : cases()) {
        const std::string out = (dir / ("r" + std::to_string(index++) + "." + c.extension));
        const std::string command = std::string(HIKARI_CLI_PATH) + " render " + HIKARI_SOURCE_DIR +
                                    "/scenes/" + c.scene + ".json " + c.options + " -q -o " + out;
        const int status = std::system(command.c_str());
        ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << command;
        const uint64_t sum = fnv1a(hikari::testing::read_text(out));
        if (print) {
            std::printf("{\"%s\", 0x%016llxull},\n", key(c).c_str(),
                        static_cast<unsigned long long>(sum));
            continue;
        }
        const auto it = pinned().find(key(c));
        ASSERT_NE(it, pinned().end()) << "no pinned checksum for " << key(c);
        EXPECT_EQ(sum, it->second) << key(c) << " renders differently";
    }
}

}  // namespace
