// Every example command of the README and of docs/classroom.md runs as written: each shell
// block is taken from the file and run in a fresh directory that holds `build/hikari` (this
// build's program) and the repository's `scenes/`, as a clean clone after the build does.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../io/temp_dir.h"

namespace {

namespace fs = std::filesystem;

using hikari::testing::read_text;

/// The ```sh blocks of a Markdown file.
std::vector<std::string> shell_blocks(const std::string& markdown) {
    std::vector<std::string> blocks;
    const std::regex block("```sh\n([\\s\\S]*?)```");
    for (auto it = std::sregex_iterator(markdown.begin(), markdown.end(), block);
         it != std::sregex_iterator(); ++it)
        blocks.push_back((*it)[1].str());
    return blocks;
}

/// A directory laid out as a built clone: build/hikari and scenes/.
fs::path clone_like_directory(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("hikari_readme_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir / "build");
    fs::create_symlink(HIKARI_CLI_PATH, dir / "build" / "hikari");
    fs::create_directory_symlink(fs::path(HIKARI_SOURCE_DIR) / "scenes", dir / "scenes");
    return dir;
}

/// Runs `script` with bash -e in `dir`; its exit status.
int run_in(const fs::path& dir, const std::string& script) {
    const fs::path file = dir / "commands.sh";
    std::ofstream(file) << script;
    const std::string command =
        "cd '" + dir.string() + "' && bash -e commands.sh > commands.log 2>&1";
    return std::system(command.c_str());
}

TEST(ReadmeCommands, EveryHikariCommandOfTheReadmeRuns) {
    const fs::path dir = clone_like_directory("readme");
    int commands = 0;
    for (const std::string& block :
         shell_blocks(read_text(fs::path(HIKARI_SOURCE_DIR) / "README.md"))) {
        std::istringstream lines(block);
        for (std::string line; std::getline(lines, line);) {
            // The build commands at the top are CI's own job; the examples start with the program.
            if (line.rfind("build/hikari", 0) != 0) continue;
            ++commands;
            EXPECT_EQ(run_in(dir, line), 0) << line << "\n" << read_text(dir / "commands.log");
        }
    }
    EXPECT_GE(commands, 10);
    fs::remove_all(dir);
}

TEST(ReadmeCommands, EveryBlockOfTheClassroomGuideRuns) {
    const fs::path dir = clone_like_directory("classroom");
    const std::vector<std::string> blocks =
        shell_blocks(read_text(fs::path(HIKARI_SOURCE_DIR) / "docs" / "classroom.md"));
    EXPECT_GE(blocks.size(), 4u);
    for (const std::string& block : blocks)
        EXPECT_EQ(run_in(dir, block), 0) << block << "\n" << read_text(dir / "commands.log");
    fs::remove_all(dir);
}

/// Every image of the README and docs/ has alt text: `![what it shows](file)`, never `![](file)`
/// (a reader who cannot see the picture is told what it shows).
TEST(ReadmeCommands, EveryImageHasAltText) {
    std::vector<fs::path> pages = {fs::path(HIKARI_SOURCE_DIR) / "README.md"};
    for (const auto& entry : fs::directory_iterator(fs::path(HIKARI_SOURCE_DIR) / "docs"))
        if (entry.path().extension() == ".md") pages.push_back(entry.path());
    const std::regex image(R"(!\[\s*\]\(|<img(?![^>]*\balt="[^"]+")[^>]*>)");
    for (const fs::path& page : pages) {
        const std::string text = read_text(page);
        std::smatch m;
        EXPECT_FALSE(std::regex_search(text, m, image))
            << page << ": an image without alt text at byte " << m.position(0);
    }
}

}  // namespace
