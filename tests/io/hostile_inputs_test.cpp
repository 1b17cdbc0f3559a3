// Hostile inputs at the loaders (issue 26): bounded reads, integers parsed exactly, memory
// checked before it is taken, and messages that say where and show input bytes escaped. Each
// case asserts the exact shape of the InputError message.

#include <sys/stat.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/input_error.h"
#include "../support/limits_restored.h"
#include "hikari/core/error.h"
#include "hikari/core/memory_budget.h"
#include "hikari/io/files/input_limits.h"
#include "hikari/io/files/printable_text.h"
#include "hikari/io/files/read_file.h"
#include "hikari/io/images/image_read.h"
#include "hikari/io/models/material_rules.h"
#include "hikari/io/models/mtl_scan.h"
#include "hikari/io/models/obj_loader.h"
#include "hikari/io/models/ply_loader.h"
#include "hikari/io/models/text_number.h"
#include "hikari/io/scene/json_reader.h"
#include "hikari/io/scene/scene_json.h"
#include "temp_dir.h"

namespace hikari {
namespace {

using testing::input_error_of;
using testing::TempDir;
using testing::write_text;

class HostileInput : public testing::LimitsRestored {};

std::string scene_error(const std::string& json) {
    return input_error_of([&] {
        std::vector<std::string> warnings;
        parse_scene(json, "s.json", "/nonexistent-hikari-test", warnings);
    });
}

/// A one-sphere scene whose camera has `camera` members.
std::string camera_scene(const std::string& camera) {
    return R"({"camera": {)" + camera +
           R"(}, "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]})";
}

// --- Escaping -----------------------------------------------------------------------------------

TEST(PrintableText, EscapesControlBytesAndBrokenUtf8) {
    EXPECT_EQ(printable_text("a\x01"
                             "b\x7f\xff\n"),
              "a\\x01b\\x7f\\xff\\x0a");
    EXPECT_EQ(printable_text("caf\xc3\xa9.obj"), "caf\xc3\xa9.obj");  // é passes
    EXPECT_EQ(printable_text("\xc3"), "\\xc3");                       // cut sequence
    EXPECT_EQ(printable_text("\xc0\xaf"), "\\xc0\\xaf");              // overlong '/'
}

// --- Bounded reads ------------------------------------------------------------------------------

TEST_F(HostileInput, EachKindHasItsLimitAndTheOptionReplacesIt) {
    EXPECT_EQ(input_limit(InputKind::scene), std::uintmax_t{256} << 20);
    EXPECT_EQ(input_limit(InputKind::mesh), std::uintmax_t{4} << 30);
    EXPECT_EQ(input_limit(InputKind::image), std::uintmax_t{1} << 30);
    const auto file = m_dir / "s.json";
    write_text(file, std::string(100, ' '));
    set_max_input_size(50);
    EXPECT_EQ(input_error_of([&] { read_file_bytes(file, InputKind::scene); }),
              file.string() +
                  ": cannot read: larger than the limit of 50 bytes for a scene file (raise it "
                  "with --max-input-size)");
    set_max_input_size(0);
    EXPECT_EQ(read_file_bytes(file, InputKind::scene).size(), 100u);
}

TEST_F(HostileInput, DevicesFifosAndDirectoriesAreRefusedByName) {
    const auto fifo = m_dir / "fifo";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(input_error_of([&] { read_file_bytes(fifo, InputKind::mesh); }),
              fifo.string() + ": cannot read: a FIFO, not a file");
    EXPECT_EQ(input_error_of([] { read_file_bytes("/dev/zero", InputKind::image); }),
              "/dev/zero: cannot read: a device, not a file");
    EXPECT_EQ(input_error_of([&] { read_file_bytes(m_dir.path(), InputKind::scene); }),
              m_dir.path().string() + ": cannot read: a directory, not a file");
}

TEST_F(HostileInput, MtllibThatIsAFifoOrDirectoryIsAnErrorAtItsLine) {
    ASSERT_EQ(::mkfifo((m_dir / "lib.mtl").c_str(), 0600), 0);
    std::filesystem::create_directory(m_dir / "dir.mtl");
    const std::string mesh = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    write_text(m_dir / "a.obj", "# a\nmtllib lib.mtl\n" + mesh);
    write_text(m_dir / "b.obj", "mtllib dir.mtl\n" + mesh);
    EXPECT_EQ(input_error_of([&] { load_obj(m_dir / "a.obj"); }),
              (m_dir / "a.obj").string() + ":2: mtllib lib.mtl: " + (m_dir / "lib.mtl").string() +
                  ": cannot read: a FIFO, not a file");
    EXPECT_EQ(input_error_of([&] { load_obj(m_dir / "b.obj"); }),
              (m_dir / "b.obj").string() + ":1: mtllib dir.mtl: " + (m_dir / "dir.mtl").string() +
                  ": cannot read: a directory, not a file");
    // A library that is missing stays a warning: OBJ files often travel without theirs.
    write_text(m_dir / "c.obj", "mtllib missing.mtl\n" + mesh);
    EXPECT_EQ(load_obj(m_dir / "c.obj").indices.size(), 1u);
}

// --- Integers parsed exactly --------------------------------------------------------------------

TEST(HostileJson, IntegersOutOfRangeNameThePath) {
    const std::string width = "s.json: camera.width: expected an integer from 1 to 65536";
    EXPECT_EQ(scene_error(camera_scene(R"("width": 2147483648)")), width + ", got 2147483648");
    EXPECT_EQ(scene_error(camera_scene(R"("width": 4294967299)")), width + ", got 4294967299");
    EXPECT_EQ(scene_error(camera_scene(R"("width": 1e10)")), width + ", got 10000000000");
    EXPECT_EQ(scene_error(camera_scene(R"("width": -5)")), width + ", got -5");
    EXPECT_EQ(scene_error(camera_scene(R"("width": 2.5)")), width);
    EXPECT_EQ(scene_error(camera_scene(R"("width": 12345678901234567890)")).substr(0, width.size()),
              width);
    EXPECT_EQ(
        scene_error(
            R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "segments": 2.5}]})"),
        "s.json: objects[0].segments: expected an integer from 3 to 4096");
}

TEST(HostileJson, NumbersBeyondAFloatAreCalledThat) {
    EXPECT_EQ(scene_error("{\n  \"camera\": {\"fov_y\": 1e400}}"),
              "s.json:2:23: 1e400 is too large for a 32-bit float");
    EXPECT_EQ(scene_error(camera_scene(R"("fov_y": 1e39)")),
              "s.json: camera.fov_y: 1e+39 is too large for a 32-bit float");
    EXPECT_EQ(scene_error(camera_scene(R"("fov_y": -1e39)")),
              "s.json: camera.fov_y: -1e+39 is too large for a 32-bit float");
}

TEST(HostileJson, InputBytesAreEscapedInMessages) {
    // A valid JSON escape that becomes a control character in the string.
    EXPECT_EQ(scene_error(R"({"objects": [{"type": "sph\u0001"}]})").substr(0, 54),
              "s.json: objects[0].type: unknown object type \"sph\\x01\"");
    // Raw bytes that are not JSON at all.
    const std::string message = scene_error("{\"objects\": [{\"type\": \"a\xff\"}]}");
    EXPECT_EQ(message.find('\xff'), std::string::npos) << message;
    EXPECT_NE(message.find("\\xff"), std::string::npos) << message;
    EXPECT_EQ(message.substr(0, 12), "s.json:1:25:");
}

class HostileObj : public HostileInput {
  protected:
    std::string obj_error(const std::string& statements) {
        const auto file = m_dir / "o.obj";
        write_text(file, "v 0 0 0\nv 1 0 0\nv 0 1 0\n" + statements);
        return input_error_of([&] { load_obj(file); });
    }
    std::string at(int line) const {
        return (m_dir / "o.obj").string() + ":" + std::to_string(line);
    }
};

TEST_F(HostileObj, IndicesAreParsedExactly) {
    const std::string corner =
        "' is not a corner (v, v/vt, v//vn or v/vt/vn, each a nonzero index of at most 10 digits "
        "that fits in 32 bits)";
    for (const std::string index :
         {"2147483648", "4294967299", "12345678901234567890", "3abc", "-2147483648", "+3"})
        EXPECT_EQ(obj_error("f 1 2 " + index + "\n"), at(4) + ": 'f': '" + index + corner);
    EXPECT_EQ(obj_error("f 1 2 0\n"), at(4) +
                                          ": 'f': '0' uses index 0; OBJ indices start at 1 "
                                          "(the first 'v' line is 1, and -1 is the last one "
                                          "read so far)");
    EXPECT_EQ(obj_error("f 1 2 -4\n"),
              at(4) + ": a relative vertex index points before the first vertex");
    EXPECT_EQ(obj_error("f 1 2 9\n"),
              at(4) + ": face refers to vertex 9, but the file defines only 3");
}

TEST_F(HostileObj, NumbersBeyondAFloatAndBinaryBytes) {
    EXPECT_EQ(obj_error("v 1e400 0 0\n"), at(4) + ": 'v': 1e400 is too large for a 32-bit float");
    EXPECT_EQ(obj_error("v 0 1e39 0\n"), at(4) + ": 'v': 1e39 is too large for a 32-bit float");
    EXPECT_EQ(obj_error("v 0 nan 0\n"), at(4) + ": 'v': 'nan' is not a finite number");
    EXPECT_EQ(obj_error("vt 1e-400 0\nf 1 2 3\n"), "");  // underflow reads as 0
    EXPECT_EQ(obj_error("f 1 2 3\x01\n"),
              at(4) +
                  ": 'f': '3\\x01' is not a corner (v, v/vt, v//vn or v/vt/vn, each a nonzero "
                  "index of at most 10 digits that fits in 32 bits)");
}

// --- MTL: numbers and the shared material rule --------------------------------------------------

class HostileMtl : public HostileInput {
  protected:
    std::string mtl_error(const std::string& statements) {
        write_text(m_dir / "m.mtl", "newmtl a\n" + statements);
        write_text(m_dir / "o.obj", "mtllib m.mtl\nusemtl a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        return input_error_of([&] { load_obj(m_dir / "o.obj"); });
    }
    std::string at(int line) const {
        return (m_dir / "m.mtl").string() + ":" + std::to_string(line);
    }
};

TEST_F(HostileMtl, ValuesTheSceneJsonRefusesAreRefused) {
    EXPECT_EQ(mtl_error("Kd -5 0 0\n"),
              at(2) + ": material 'a', Kd: kd must be finite and not negative, got (-5, 0, 0)");
    EXPECT_EQ(mtl_error("Ns 10\nNs -50\n"),
              at(3) + ": material 'a', Ns: shininess must be a finite number >= 0, got -50");
    EXPECT_EQ(mtl_error("Ni 0\n"),
              at(2) + ": material 'a', Ni: ior must be a finite number > 0, got 0");
    EXPECT_EQ(mtl_error("d 2\n"),
              at(2) + ": material 'a', d: transparency must be from 0 to 1, got -1");
    EXPECT_EQ(mtl_error("Tr -1\n"),
              at(2) + ": material 'a', Tr: transparency must be from 0 to 1, got -1");
    EXPECT_EQ(
        mtl_error("Ke 0 -1 0\n"),
        at(2) + ": material 'a', Ke: emission must be finite and not negative, got (0, -1, 0)");
    EXPECT_EQ(mtl_error("Kd 0.5 0.5 0.5\nNs 50\nNi 1.5\nd 0.5\nillum 2\n"), "");
}

TEST_F(HostileMtl, NumbersAreParsedExactly) {
    EXPECT_EQ(mtl_error("Kd abc 1 1\n"), at(2) + ": 'Kd': 'abc' is not a finite number");
    EXPECT_EQ(mtl_error("Kd 1e400 1 1\n"), at(2) + ": 'Kd': 1e400 is too large for a 32-bit float");
    EXPECT_EQ(mtl_error("Ns 1e39\n"), at(2) + ": 'Ns': 1e39 is too large for a 32-bit float");
    EXPECT_EQ(mtl_error("Ns 5x\n"), at(2) + ": 'Ns': '5x' is not a finite number");
    EXPECT_EQ(mtl_error("Kd 1 1 1 1\n"), at(2) + ": 'Kd' needs 1 to 3 numbers, found 4");
    EXPECT_EQ(mtl_error("d\n"), at(2) + ": 'd' needs 1 number, found 0");
    for (const std::string illum : {"4294967299", "99999999999999999999", "-1", "11", "2.5"})
        EXPECT_EQ(mtl_error("illum " + illum + "\n"),
                  at(2) + ": 'illum' needs one integer from 0 to 10, found '" + illum + "'");
    EXPECT_EQ(mtl_error("Kd \x02 1 1\n"), at(2) + ": 'Kd': '\\x02' is not a finite number");
}

TEST(MtlScan, RecordsEachMaterialsStatementLines) {
    const auto materials =
        scan_mtl_text("m.mtl", "# c\nnewmtl a\nKd 1 1 1\n\nnewmtl b c\nNs 2\r\nNs 3\n");
    ASSERT_EQ(materials.size(), 2u);
    EXPECT_EQ(materials[0].name, "a");
    EXPECT_EQ(materials[0].line_of("Kd"), 3u);
    EXPECT_EQ(materials[0].line_of("Ns"), 2u);  // absent: the newmtl line
    EXPECT_EQ(materials[1].name, "b c");
    EXPECT_EQ(materials[1].line_of("Ns"), 7u);  // the last one, as tinyobjloader keeps it
}

TEST(MaterialRules, OneRuleForEveryFormat) {
    Material m;
    EXPECT_FALSE(find_material_problem(m));
    m.reflectivity = 1.5f;
    ASSERT_TRUE(find_material_problem(m));
    EXPECT_EQ(find_material_problem(m)->field, MaterialField::reflectivity);
    // The scene JSON applies it too.
    EXPECT_EQ(scene_error(R"({"materials": {"m": {"transparency": 2}}, "objects": []})"),
              "s.json: materials.m.transparency: transparency must be from 0 to 1, got 2");
}

TEST(TextNumber, FloatTokens) {
    EXPECT_EQ(parse_float_token("+1.5"), 1.5f);
    EXPECT_EQ(parse_float_token("-2e3"), -2000.0f);
    EXPECT_EQ(parse_float_token("1e-50"), 0.0f);
    std::string why;
    EXPECT_FALSE(parse_float_token("-1e39", &why));
    EXPECT_EQ(why, "-1e39 is too large for a 32-bit float");
    EXPECT_FALSE(parse_float_token("inf", &why));
    EXPECT_EQ(why, "'inf' is not a finite number");
    EXPECT_FALSE(parse_float_token("", &why));
}

// --- Memory checked before it is taken ----------------------------------------------------------

TEST_F(HostileObj, ManyFacesAreRefusedBeforeTheyAreParsed) {
    std::string faces;
    for (int i = 0; i < 20000; ++i) faces += "f 1 1 1\n";
    set_memory_limit(1 << 20);
    // The memory message, not "all are degenerate": refused before tinyobjloader and the mesh
    // builder ran.
    const std::string e = obj_error(faces);
    EXPECT_EQ(e.rfind((m_dir / "o.obj").string() + ": loading 20000 faces needs about ", 0), 0u)
        << e;
    EXPECT_NE(e.find(" MiB, more than the limit of 1 MiB (raise it with --max-memory 0.0"),
              std::string::npos)
        << e;
    EXPECT_TRUE(e.ends_with(" or more)")) << e;
}

TEST_F(HostileInput, PlyHeaderCountsAreCheckedAgainstMemory) {
    // Binary: 10000 vertices of 3 floats, present in the file, no faces.
    std::string ply =
        "ply\nformat binary_little_endian 1.0\nelement vertex 10000\nproperty float x\n"
        "property float y\nproperty float z\nend_header\n";
    ply.append(10000 * 12, '\0');
    set_memory_limit(100000);
    EXPECT_EQ(input_error_of([&] { read_ply("p.ply", ply); }).substr(0, 56),
              "p.ply: loading 10000 vertices and 0 faces needs about 0.");
}

TEST_F(HostileInput, ImagesAreCheckedAgainstMemoryBeforeDecoding) {
    const auto file = m_dir / "t.ppm";
    write_text(file, "P6\n512 512\n255\n" + std::string(512 * 512 * 3, '\x80'));
    set_memory_limit(1 << 20);
    const std::string e = input_error_of([&] { read_image(file); });
    EXPECT_EQ(e.rfind(file.string() + ": decoding a 512x512 image needs about ", 0), 0u) << e;
    EXPECT_NE(e.find(" MiB, more than the limit of 1 MiB (raise it with --max-memory 0.0"),
              std::string::npos)
        << e;
    EXPECT_TRUE(e.ends_with(" or more)")) << e;
}

}  // namespace
}  // namespace hikari
