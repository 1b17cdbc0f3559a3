// Methods own their capabilities (issue 39, ARCHITECTURE.md "a method is one registry entry"):
// what a method offers — options, AOVs, explain views, stats words, SVG output — is said by its
// entry in methods/registry.cpp, so no code outside the registry needs to compare a method's
// name. This test looks for the names as string literals in src/ and apps/ outside methods/;
// choosing one method by its name (`find_method("path")`, B5's path tracer) is not asking what
// a method offers, and is allowed.

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "hikari/methods/registry.h"

namespace hikari {
namespace {

namespace fs = std::filesystem;

/// Files where a method's name is data, not a comparison: the gallery's figures are command
/// lines (`{"-m", "zbuffer"}`) run by `hikari render`.
const std::set<std::string> k_names_as_arguments = {"apps/hikari/gallery.cpp",
                                                    "apps/hikari/gallery_figures.cpp"};

/// Whether `line` (code, not a comment) holds `name` as a whole string literal other than the
/// argument of find_method.
bool names_literally(const std::string& line, std::string_view name) {
    const size_t code = line.find_first_not_of(" \t");
    if (code != std::string::npos && line.compare(code, 2, "//") == 0) return false;
    const size_t comment = line.find("//");
    const std::string literal = "\"" + std::string(name) + "\"";
    for (size_t at = line.find(literal); at != std::string::npos && at < comment;
         at = line.find(literal, at + 1)) {
        static constexpr std::string_view k_lookup = "find_method(";
        if (at < k_lookup.size() || line.compare(at - k_lookup.size(), k_lookup.size(), k_lookup))
            return true;
    }
    return false;
}

TEST(MethodNames, NoCodeOutsideTheRegistryNamesAMethod) {
    const fs::path root(HIKARI_SOURCE_DIR);
    int files = 0;
    for (const char* top : {"src", "apps"}) {
        for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
            const std::string relative = fs::relative(entry.path(), root).generic_string();
            if (!entry.is_regular_file() || relative.starts_with("src/hikari/methods/") ||
                k_names_as_arguments.count(relative))
                continue;
            if (entry.path().extension() != ".cpp" && entry.path().extension() != ".h") continue;
            std::ifstream in(entry.path());
            std::string line;
            for (int number = 1; std::getline(in, line); ++number)
                for (const Method& m : methods())
                    EXPECT_FALSE(names_literally(line, m.name))
                        << relative << ":" << number << " names method " << m.name
                        << "; say what it offers in its registry entry instead: " << line;
            ++files;
        }
    }
    EXPECT_GT(files, 100);
}

TEST(MethodNames, TheScanSeesALiteralButNotAComment) {
    EXPECT_TRUE(names_literally(R"(    if (method.name == "zbuffer") {)", "zbuffer"));
    EXPECT_TRUE(names_literally(R"(    {Aov::overdraw, "depthsort"},)", "depthsort"));
    EXPECT_FALSE(names_literally(R"(    // as "zbuffer" does)", "zbuffer"));
    EXPECT_FALSE(names_literally(R"(    "explain -m zbuffer needs --pixel")", "zbuffer"));
    EXPECT_FALSE(names_literally(R"(    render_scene(*find_method("path"), scene)", "path"));
    EXPECT_TRUE(names_literally(R"(    find_method("path") && name == "path")", "path"));
}

}  // namespace
}  // namespace hikari
