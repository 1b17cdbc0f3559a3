// Hostile inputs through the hikari program (issue 26), the loaders' side: each is refused with
// exit status 1, one `hikari: error:` line that says where, and no output file. The command
// line's own cases (output names, options, signals) are in hostile_command_line_test.cpp.

#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "../io/temp_dir.h"

#include "run_hikari.h"

namespace {

namespace fs = std::filesystem;

using Result = hikari::testing::RunResult;
using hikari::testing::run_hikari;

class HostileCli : public ::testing::Test {
  protected:
    std::string path(const std::string& name) const { return (m_dir / name).string(); }
    void write(const std::string& name, const std::string& bytes) const {
        hikari::testing::write_text(m_dir / name, bytes);
    }
    /// `hikari render INPUT OPTIONS -o out.png` fails with exit 1 and the one line
    /// "hikari: error: " + message, and writes nothing.
    void expect_refused(const std::string& input, const std::string& message,
                        const std::string& options = "") const {
        const Result r =
            run_hikari("render -q " + input + " " + options + " -o " + path("out.png"));
        EXPECT_EQ(r.status, 1) << input << ": " << r.output;
        EXPECT_EQ(r.output, "hikari: error: " + message + "\n");
        EXPECT_FALSE(fs::exists(path("out.png")));
    }

    hikari::testing::TempDir m_dir;
};

const std::string k_triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

TEST_F(HostileCli, DevicesAndFifosAsEveryKindOfInput) {
    ASSERT_EQ(::mkfifo(path("fifo").c_str(), 0600), 0);
    expect_refused(path("fifo"), path("fifo") + ": cannot read: a FIFO, not a file");
    expect_refused("/dev/zero", "/dev/zero: cannot read: a device, not a file");
    // A mesh named by a scene.
    ASSERT_EQ(::mkfifo(path("fifo.obj").c_str(), 0600), 0);
    write("s.json", R"({"objects": [{"type": "mesh", "file": "fifo.obj"}]})");
    expect_refused(path("s.json"), path("s.json") + ": objects[0].file: " + path("fifo.obj") +
                                       ": cannot read: a FIFO, not a file");
    // An OBJ's mtllib.
    write("m.obj", "mtllib fifo\n" + k_triangle);
    expect_refused(path("m.obj"), path("m.obj") + ":1: mtllib fifo: " + path("fifo") +
                                      ": cannot read: a FIFO, not a file");
    // A texture named by an MTL file.
    write("t.mtl", "newmtl a\nmap_Kd fifo.png\n");
    ASSERT_EQ(::mkfifo(path("fifo.png").c_str(), 0600), 0);
    write("t.obj", "mtllib t.mtl\nusemtl a\nvt 0 0\n" + k_triangle);
    expect_refused(path("t.obj"), path("t.mtl") +
                                      ":2: map_Kd of material 'a': cannot use texture "
                                      "\"fifo.png\": " +
                                      path("fifo.png") + ": cannot read: a FIFO, not a file");
    // A glTF buffer.
    write("g.gltf",
          R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "fifo", "byteLength": 36}]})");
    expect_refused(path("g.gltf"),
                   path("g.gltf") + ": " + path("fifo") + ": cannot read: a FIFO, not a file");
}

TEST_F(HostileCli, MaxInputSizeBoundsEveryRead) {
    write("m.obj", k_triangle);
    expect_refused(path("m.obj"),
                   path("m.obj") +
                       ": cannot read: larger than the limit of 1 bytes for a mesh file (raise it "
                       "with --max-input-size)",
                   "--max-input-size 1e-9");
    EXPECT_EQ(run_hikari("render -q " + path("m.obj") +
                         " --width 8 --height 8 --max-input-size 0.001 -o " + path("ok.png"))
                  .status,
              0);
}

TEST_F(HostileCli, IntegersAndFloatsOutOfRange) {
    write("big.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4294967299\n");
    expect_refused(path("big.obj"),
                   path("big.obj") +
                       ":4: 'f': '4294967299' is not a corner (v, v/vt, v//vn or v/vt/vn, each a "
                       "nonzero index of at most 10 digits that fits in 32 bits)");
    write("w.json", R"({"camera": {"width": 4294967299}, "objects": []})");
    expect_refused(
        path("w.json"),
        path("w.json") + ": camera.width: expected an integer from 1 to 65536, got 4294967299");
    write("f.json", "{\"camera\": {\"fov_y\": 1e400}, \"objects\": []}");
    expect_refused(path("f.json"), path("f.json") + ":1:22: 1e400 is too large for a 32-bit float");
    write("k.mtl", "newmtl a\nKd -5 0 0\n");
    write("k.obj", "mtllib k.mtl\nusemtl a\n" + k_triangle);
    expect_refused(
        path("k.obj"),
        path("k.mtl") + ":2: material 'a', Kd: kd must be finite and not negative, got (-5, 0, 0)");
}

TEST_F(HostileCli, BinaryBytesAreEscaped) {
    // Raw bytes that break the JSON, and control characters written as JSON escapes.
    write("b.json", "{\"objects\": [{\"type\": \"\xff\x1b[31m\"}]}");
    const Result r = run_hikari("render -q " + path("b.json") + " -o " + path("out.png"));
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.output.rfind("hikari: error: " + path("b.json") + ":1:24: ", 0), 0u) << r.output;
    EXPECT_NE(r.output.find("\\xff"), std::string::npos) << r.output;
    write("e.json", R"({"objects": [{"type": "\u001b[31m"}]})");
    const Result e = run_hikari("render -q " + path("e.json") + " -o " + path("out.png"));
    EXPECT_EQ(e.status, 1);
    EXPECT_NE(e.output.find("unknown object type \"\\x1b[31m\""), std::string::npos) << e.output;
    for (const std::string& output : {r.output, e.output}) {
        EXPECT_EQ(std::count(output.begin(), output.end(), '\x1b'), 0) << output;
        EXPECT_EQ(std::count(output.begin(), output.end(), '\n'), 1) << output;
    }
}

TEST_F(HostileCli, TenMillionFacesAreRefusedUnderMaxMemory) {
    {
        std::ofstream out(path("faces.obj"), std::ios::binary);
        out << "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
        std::string block;
        for (int i = 0; i < 10000; ++i) block += "f 1 1 1\n";
        for (int i = 0; i < 1000; ++i) out << block;
    }
    const Result r =
        run_hikari("render -q " + path("faces.obj") + " --max-memory 0.5 -o " + path("out.png"));
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(
        r.output.rfind(
            "hikari: error: " + path("faces.obj") + ": loading 10000000 faces needs about ", 0),
        0u)
        << r.output;
    EXPECT_NE(r.output.find("more than the limit of 0.5 GiB (raise it with --max-memory "),
              std::string::npos);
    EXPECT_FALSE(fs::exists(path("out.png")));
}

}  // namespace
