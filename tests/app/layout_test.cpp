// The layout's rule (ARCHITECTURE.md, "Floors"): a file of src/hikari/ includes files of its own
// floor or of floors below, never above, so each pipeline stage can be read, built and tested
// on top of what it stands on.
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>

#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;

/// Floors, ground up; folders on one floor may include each other.
const std::map<std::string, int>& floors() {
    static const std::map<std::string, int> table = {
        {"core", 0},  {"scene", 1},   {"shading", 2}, {"geometry", 2},    {"bvh", 2},
        {"frame", 2}, {"io", 2},      {"raster", 3},  {"integrators", 3}, {"methods", 4},
        {"bench", 4}, {"explain", 4}, {"session", 5},
    };
    return table;
}

TEST(Layout, NoIncludeRunsUpAFloor) {
    const fs::path src = fs::path(HIKARI_SOURCE_DIR) / "src" / "hikari";
    const std::regex include(R"(#include "hikari/([a-z_]+)/)");
    int files = 0, includes = 0;
    for (const auto& entry : fs::recursive_directory_iterator(src)) {
        if (!entry.is_regular_file()) continue;
        const std::string folder = fs::relative(entry.path(), src).begin()->string();
        ASSERT_TRUE(floors().count(folder)) << "folder " << folder << " has no floor";
        const int floor = floors().at(folder);
        std::ifstream in(entry.path());
        std::string line;
        while (std::getline(in, line)) {
            std::smatch m;
            if (!std::regex_search(line, m, include) || !floors().count(m[1].str())) continue;
            EXPECT_LE(floors().at(m[1].str()), floor)
                << entry.path().string() << " includes " << line;
            ++includes;
        }
        ++files;
    }
    EXPECT_GT(files, 50);
    EXPECT_GT(includes, 200);
}

}  // namespace
