// Hostile inputs, round 3 (issue 41) at the loaders: whole files checked from their first bytes
// and against --max-memory before they are read (sparse multi-GiB files, peak memory measured),
// bounded printable messages, faces capped in every format, degenerate light directions.

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "../support/input_error.h"
#include "../support/limits_restored.h"
#include "../support/peak_memory.h"
#include "hikari/core/memory_budget.h"
#include "hikari/io/files/input_limits.h"
#include "hikari/io/files/printable_text.h"
#include "hikari/io/files/read_file.h"
#include "hikari/io/images/image_read.h"
#include "hikari/io/images/image_write.h"
#include "hikari/io/models/gltf_loader.h"
#include "hikari/io/models/obj_loader.h"
#include "hikari/io/models/ply_loader.h"
#include "hikari/io/scene/scene_json.h"
#include "hikari/io/scene/scene_overrides.h"
#include "scene_test_util.h"
#include "temp_dir.h"

namespace hikari {
namespace {

using testing::input_error_of;
using testing::TempDir;

constexpr double k_gib = double(1 << 30);

/// A sparse file of `bytes` (no disk taken) that starts with `head`.
void write_sparse(const std::filesystem::path& path, const std::string& head, off_t bytes) {
    testing::write_text(path, head);
    const int fd = ::open(path.c_str(), O_WRONLY);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(::ftruncate(fd, bytes), 0);
    ::close(fd);
}

class HostileRound3 : public testing::LimitsRestored {};

TEST_F(HostileRound3, PlyMagicIsCheckedBeforeTheFileIsRead) {
    const auto file = m_dir / "big.ply";
    write_sparse(file, "not a ply\n", off_t{3} << 30);
    set_memory_limit(8 * k_gib);  // room for the file: only its magic refuses it
    const auto run = testing::run_in_child([&] { load_ply(file); });
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_LT(run.extra_peak_bytes, 64.0 * (1 << 20));
    EXPECT_EQ(input_error_of([&] { load_ply(file); }),
              file.string() + ":1: not a PLY file (the first line is not 'ply')");
}

TEST_F(HostileRound3, GlbHeaderIsCheckedBeforeTheFileIsRead) {
    const auto file = m_dir / "big.glb";
    // "glTF", version 1: refused from the 12-byte header.
    write_sparse(file, std::string("glTF\x01\0\0\0\x20\0\0\0", 12), off_t{3} << 30);
    set_memory_limit(8 * k_gib);
    const auto run = testing::run_in_child([&] { load_gltf(file); });
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_LT(run.extra_peak_bytes, 64.0 * (1 << 20));
    EXPECT_EQ(input_error_of([&] { load_gltf(file); }),
              file.string() + ": GLB version 1 (only version 2 is read)");
    set_max_input_size(std::uintmax_t{8} << 30);  // past the mesh limit: tinygltf's own refuses
    write_sparse(file, std::string("glTF\x02\0\0\0\x20\0\0\0", 12), off_t{5} << 30);
    EXPECT_EQ(input_error_of([&] { load_gltf(file); }),
              file.string() + ": a glTF or GLB file must be smaller than 4 GiB");
}

TEST_F(HostileRound3, ObjTextAndItsTableAreCheckedAgainstTheMemoryLimit) {
    const auto file = m_dir / "big.obj";
    write_sparse(file, "v 0 0 0\n", off_t{1} << 30);
    set_memory_limit(1.5 * k_gib);
    const auto run = testing::run_in_child([&] { load_obj(file); });
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_LT(run.extra_peak_bytes, 64.0 * (1 << 20));
    EXPECT_EQ(input_error_of([&] { load_obj(file); }),
              "reading the OBJ file " + file.string() +
                  " (1 GiB) needs about 2 GiB, more than the limit of 1.5 GiB (raise it "
                  "with --max-memory 2 or more)");
}

/// A scene of `count` mesh objects that all name `file`.
std::string scene_of_copies(const std::string& file, int count) {
    std::string objects;
    for (int i = 0; i < count; ++i)
        objects += std::string(i ? ", " : "") + R"({"type": "mesh", "file": ")" + file +
                   R"(", "transform": [{"translate": [)" + std::to_string(i) + ", 0, 0]}]}";
    return R"({"objects": [)" + objects + "]}";
}

TEST_F(HostileRound3, AModelManyObjectsNameIsLoadedOnce) {
    // The second triangle is degenerate: its warning is said once, not once per object.
    testing::write_text(m_dir / "t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 1 2\n");
    std::vector<std::string> warnings;
    const Scene scene = parse_scene(scene_of_copies("t.obj", 3), "s.json", m_dir.path(), warnings);
    EXPECT_EQ(scene.triangles.size(), 3u);
    EXPECT_EQ(scene.triangles.positions[6].x, 2.0f);  // each copy moved by its own transform
    EXPECT_EQ(std::count_if(
                  warnings.begin(), warnings.end(),
                  [](const std::string& w) { return w.find("degenerate") != std::string::npos; }),
              1);
}

TEST_F(HostileRound3, CopiesOfOneModelAreCheckedAgainstTheMemoryLimit) {
    // 300 objects of one scan took 6.8 GB under a 1 GiB limit: no file is large, the copies are.
    std::string obj;
    for (int i = 0; i < 2000; ++i) obj += fmt::format("v {} 0 0\nv {} 1 0\nv {} 0 1\n", i, i, i);
    for (int i = 0; i < 2000; ++i)
        obj += fmt::format("f {} {} {}\n", 3 * i + 1, 3 * i + 2, 3 * i + 3);
    testing::write_text(m_dir / "m.obj", obj);
    set_memory_limit(8 << 20);
    std::vector<std::string> warnings;
    const std::string e = input_error_of(
        [&] { parse_scene(scene_of_copies("m.obj", 2000), "s.json", m_dir.path(), warnings); });
    EXPECT_EQ(e.rfind("s.json: objects[", 0), 0u) << e;
    EXPECT_NE(e.find("].file: 2000 triangles of \"m.obj\" after the scene's "), std::string::npos)
        << e;
    EXPECT_NE(e.find("more than the limit of 8 MiB (raise it with --max-memory "),
              std::string::npos)
        << e;
}

TEST(QuoteToken, ShortTokensAreQuotedWhole) {
    EXPECT_EQ(quote_token("12a"), "'12a'");
    EXPECT_EQ(quote_token("name", '"'), "\"name\"");
    EXPECT_EQ(quote_token("out.png", '\0'), "out.png");
}

TEST(QuoteToken, LongTokensAreCutAndTheirSizeSaid) {
    const std::string token(200'000, '1');
    EXPECT_EQ(quote_token(token), "'" + std::string(40, '1') + "\u2026' (200000 bytes)");
}

TEST(QuoteToken, ControlCharactersAreEscapedAndCharactersNotSplit) {
    EXPECT_EQ(quote_token("a\x1b[31m"), "'a\\x1b[31m'");
    // 39 ASCII bytes, then a 2-byte é across the cut at 40: the cut backs off to 39.
    const std::string token = std::string(39, 'a') + "\xc3\xa9" + std::string(10, 'b');
    EXPECT_EQ(quote_token(token), "'" + std::string(39, 'a') + "\u2026' (51 bytes)");
}

TEST_F(HostileRound3, AHugeNumberMakesAOneLineMessage) {
    testing::write_text(m_dir / "n.obj", "v " + std::string(1'000'000, '1') + " 0 0\n");
    const std::string error = input_error_of([&] { load_obj(m_dir / "n.obj"); });
    EXPECT_LT(error.size(), 300u) << error.substr(0, 300);
    EXPECT_NE(error.find("(1000000 bytes) is too large for a 32-bit float"), std::string::npos);
    const std::string ply_error = input_error_of([&] {
        read_ply("p.ply",
                 "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                 "property float y\nproperty float z\nend_header\n" +
                     std::string(100'000, '7') + "x 0 0\n");
    });
    EXPECT_LT(ply_error.size(), 300u) << ply_error.substr(0, 300);
}

TEST(HostileRound3Json, LongTokensInSceneJsonAreCut) {
    const std::string error =
        testing::error_of("{\"objects\": [], \"" + std::string(5000, 'k') + "\": 1}");
    EXPECT_LT(error.size(), 300u) << error.substr(0, 300);
    EXPECT_NE(error.find("(5000 bytes)"), std::string::npos) << error;
    const std::string syntax =
        testing::error_of("{\"objects\": [" + std::string(100'000, '9') + "x]}");
    EXPECT_LT(syntax.size(), 300u) << syntax.substr(0, 300);
}

TEST(HostileRound3Set, SetArgumentsAreEscapedAndCut) {
    const std::string error =
        input_error_of([] { parse_scene_override("a\x1b[2J" + std::string(1000, 'x') + "=["); });
    EXPECT_EQ(error.find('\x1b'), std::string::npos);
    EXPECT_LT(error.size(), 300u) << error;
}

TEST(HostileRound3Ply, FacesOfMoreThan255CornersAreRefused) {
    std::string ply =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uint int vertex_indices\n"
        "end_header\n0 0 0\n1 0 0\n0 1 0\n256";
    for (int i = 0; i < 256; ++i) ply += i % 3 == 0 ? " 0" : i % 3 == 1 ? " 1" : " 2";
    EXPECT_EQ(input_error_of([&] { read_ply("f.ply", ply + "\n"); }),
              "f.ply:13: face 0: it has 256 corners; a face needs 3 to 255");
}

TEST(HostileRound3Light, TinyAndHugeDirectionsNormalizeWithoutNaN) {
    for (const char* direction : {"[0, -1e-30, 0]", "[0, -1e30, 0]", "[0, -1e-38, 0]"}) {
        const Scene s =
            testing::parse(std::string(R"({"lights": [{"type": "directional", "direction": )") +
                           direction + R"(, "intensity": 1}], "objects": []})");
        const auto& light = std::get<DirectionalLight>(s.lights[0]);
        EXPECT_FLOAT_EQ(light.direction.y, -1.0f) << direction;
        EXPECT_FALSE(std::isnan(light.direction.x)) << direction;
    }
}

TEST_F(HostileRound3, ExrTooShortForItsChunkTableIsTruncated) {
    // A real 16 × 65536 EXR cut to 2000 bytes: its header (a few hundred bytes) is whole, the
    // table of at least 2048 chunk offsets (16 KiB) is not.
    write_image(m_dir / "tall.exr", Image(16, 65536, Vec3(0.5f)));
    const std::string bytes = read_file_bytes(m_dir / "tall.exr");
    testing::write_text(m_dir / "cut.exr", bytes.substr(0, 2000));
    const std::string error = input_error_of([&] { read_image(m_dir / "cut.exr"); });
    EXPECT_NE(error.find("truncated file: its 16x65536 image needs"), std::string::npos) << error;
    EXPECT_EQ(read_image(m_dir / "tall.exr").height, 65536);
}

}  // namespace
}  // namespace hikari
