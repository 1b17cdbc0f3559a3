// The OBJ loader's streaming pass (issue 26): faces go straight into hikari's own compact arrays
// through tinyobjloader's callback parser, degenerate triangles are dropped as they come, the
// statements that set state (usemtl, s, mtllib, g) mean what tinyobjloader's LoadObj made of
// them, and the load can be cancelled.

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "../../support/obj_text.h"
#include "../temp_dir.h"
#include "hikari/core/cancel.h"
#include "hikari/core/error.h"
#include "hikari/core/memory_budget.h"
#include "hikari/io/models/obj_loader.h"

namespace hikari {
namespace {

using testing::k_obj_quad;
using testing::obj_load_error;
using testing::TempDir;
using testing::write_text;

/// `count` copies of `line`.
std::string repeated(const std::string& line, size_t count) {
    std::string out;
    out.reserve(line.size() * count);
    for (size_t i = 0; i < count; ++i) out += line;
    return out;
}

/// Restores the memory limit a test changes.
class ObjStreaming : public ::testing::Test {
  protected:
    void TearDown() override { set_memory_limit(m_memory); }
    TempDir m_dir;

  private:
    double m_memory = memory_limit();
};

TEST_F(ObjStreaming, DegenerateFloodIsRefusedUnderASmallMemoryLimit) {
    // A million degenerate faces: refused from the counts alone, before any face is stored (the
    // limit holds the 7.6 MiB text and its line table, twice the file, checked before reading).
    write_text(m_dir / "d.obj", std::string(k_obj_quad) + repeated("f 1 1 1\n", 1000000));
    set_memory_limit(16 << 20);
    const std::string e = obj_load_error(m_dir / "d.obj");
    EXPECT_EQ(e.rfind((m_dir / "d.obj").string() + ": loading 1000000 faces needs about ", 0), 0u)
        << e;
    EXPECT_NE(e.find("more than the limit of 16 MiB (raise it with --max-memory "),
              std::string::npos)
        << e;
}

TEST_F(ObjStreaming, RefusedUpFrontWhenBuildingTheMeshWouldPassTheLimit) {
    // 100,000 triangles: the loader's arrays (about 7.6 MiB) fit under 12 MiB, but build_mesh
    // runs while they are held and needs about 13 MiB more (its parallel passes keep every
    // corner's normal and variant). The file is refused from the scan's counts, not after the
    // seconds of loading it.
    write_text(m_dir / "t.obj", std::string(k_obj_quad) + repeated("f 1 2 3\n", 100000));
    set_memory_limit(12 << 20);
    const std::string e = obj_load_error(m_dir / "t.obj");
    EXPECT_EQ(e.rfind((m_dir / "t.obj").string() + ": loading 100000 faces needs about 20.", 0), 0u)
        << e;
    set_memory_limit(22 << 20);
    EXPECT_EQ(obj_load_error(m_dir / "t.obj"), "");
}

TEST_F(ObjStreaming, DegenerateFloodIsCountedInTheError) {
    // Repeated indices, and distinct vertices at one point: both have zero area.
    write_text(m_dir / "d.obj", std::string(k_obj_quad) + repeated("f 1 1 1\n", 100000) +
                                    "v 0 0 0\n" + repeated("f 1 5 -1\n", 100000));
    EXPECT_EQ(obj_load_error(m_dir / "d.obj"),
              (m_dir / "d.obj").string() + ": no usable triangles: all 200000 are degenerate");
}

TEST_F(ObjStreaming, DroppedTrianglesAddToTheMeshBuildersCount) {
    // Two dropped as they stream in (zero area), one polygon left to build_mesh that is
    // degenerate too (collinear): the error counts all three.
    write_text(m_dir / "d.obj",
               std::string(k_obj_quad) + "v 2 0 0\nv 3 0 0\nf 1 1 1\nf 1 2 2\nf 1 2 5 6\n");
    EXPECT_EQ(obj_load_error(m_dir / "d.obj"),
              (m_dir / "d.obj").string() + ": no usable triangles: all 4 are degenerate");
    // With a usable triangle after them, the count is a warning's and the triangle stays.
    write_text(m_dir / "k.obj", std::string(k_obj_quad) + "f 1 1 1\nf 3 3 4\nf 1 2 3\n");
    const MeshData mesh = load_obj(m_dir / "k.obj");
    EXPECT_EQ(mesh.degenerate_skipped, 2u);
    ASSERT_EQ(mesh.indices.size(), 1u);
    EXPECT_EQ(mesh.positions[mesh.indices[0][2]], Vec3(1, 1, 0));
}

TEST_F(ObjStreaming, DegenerateTriangleWithABadIndexIsStillAnError) {
    // Not dropped unchecked: its normal index is out of range, and that names the line.
    write_text(m_dir / "n.obj", std::string(k_obj_quad) + "f 1 2 3\nf 1//9 1//9 1//9\n");
    EXPECT_EQ(
        obj_load_error(m_dir / "n.obj"),
        (m_dir / "n.obj").string() + ":6: face refers to normal 9, but the file defines only 0");
}

TEST_F(ObjStreaming, ForwardReferencesStillWork) {
    // Faces before the vertices they name: valid OBJ, resolved once the whole file is read.
    write_text(m_dir / "f.obj", std::string("f 1 2 3\nf 1 1 2\n") + k_obj_quad);
    const MeshData mesh = load_obj(m_dir / "f.obj");
    ASSERT_EQ(mesh.indices.size(), 1u);
    EXPECT_EQ(mesh.degenerate_skipped, 1u);
}

TEST_F(ObjStreaming, UsemtlReadsItsFirstWordAsLoadObjDid) {
    write_text(m_dir / "m.mtl", "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n");
    // Blanks around the name, and no blank after the keyword at all: the first word counts.
    write_text(m_dir / "m.obj", std::string("mtllib m.mtl\n") + k_obj_quad +
                                    "usemtl  blue  \nf 1 2 3\nusemtlred\nf 1 3 4\n"
                                    "usemtl nothing\nf 2 3 4\n");
    const MeshData mesh = load_obj(m_dir / "m.obj");
    ASSERT_EQ(mesh.material.size(), 3u);
    ASSERT_EQ(mesh.materials.size(), 2u);
    EXPECT_EQ(mesh.materials[mesh.material[0]].name, "blue");
    EXPECT_EQ(mesh.materials[mesh.material[1]].name, "red");
    EXPECT_EQ(mesh.material[2], -1);
    ASSERT_EQ(mesh.warnings.size(), 1u);
    EXPECT_EQ(mesh.warnings[0],
              (m_dir / "m.obj").string() + ": material [ 'nothing' ] not found in .mtl");
}

TEST_F(ObjStreaming, UsemtlBeforeItsLibraryFindsNothing) {
    write_text(m_dir / "m.mtl", "newmtl red\nKd 1 0 0\n");
    write_text(m_dir / "m.obj", std::string(k_obj_quad) +
                                    "usemtl red\nf 1 2 3\nmtllib m.mtl\nusemtl red\nf 1 3 4\n");
    const MeshData mesh = load_obj(m_dir / "m.obj");
    ASSERT_EQ(mesh.material.size(), 2u);
    EXPECT_EQ(mesh.material[0], -1);
    EXPECT_EQ(mesh.material[1], 0);
}

TEST_F(ObjStreaming, MissingMaterialWarningsAreBounded) {
    // Ten thousand usemtl lines naming nothing: a hundred warnings and a count, not ten thousand.
    write_text(m_dir / "m.obj",
               std::string(k_obj_quad) + repeated("usemtl nope\n", 10000) + "f 1 2 3\n");
    const MeshData mesh = load_obj(m_dir / "m.obj");
    ASSERT_EQ(mesh.warnings.size(), 101u);
    EXPECT_EQ(mesh.warnings.back(),
              (m_dir / "m.obj").string() +
                  ": 9900 more usemtl statements name materials not found in .mtl");
}

TEST_F(ObjStreaming, SmoothingGroupsFollowTheirStatements) {
    // A folded strip: two triangles at a right angle. In one smoothing group their shared corners
    // get one averaged normal (fewer vertices); `s off` between them keeps them apart.
    const std::string fold = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
    write_text(m_dir / "one.obj", fold + "s 1\nf 1 2 3\nf 1 4 2\n");
    write_text(m_dir / "off.obj", fold + "s 1\nf 1 2 3\ns off\nf 1 4 2\n");
    write_text(m_dir / "neg.obj", fold + "s 1\nf 1 2 3\ns -4\nf 1 4 2\n");  // negative: off
    EXPECT_EQ(load_obj(m_dir / "one.obj").positions.size(), 4u);
    EXPECT_EQ(load_obj(m_dir / "off.obj").positions.size(), 6u);
    EXPECT_EQ(load_obj(m_dir / "neg.obj").positions.size(), 6u);
}

TEST_F(ObjStreaming, LineStatementWithZeroIndexFailsAsLoadObjDid) {
    write_text(m_dir / "l.obj", std::string(k_obj_quad) + "f 1 2 3\nl 1 0\n");
    EXPECT_EQ(
        obj_load_error(m_dir / "l.obj"),
        (m_dir / "l.obj").string() + ":6: Failed parse `l' line(e.g. zero value for vertex index)");
    write_text(m_dir / "ok.obj", std::string(k_obj_quad) + "f 1 2 3\nl 1 2\np 1\n");
    EXPECT_EQ(load_obj(m_dir / "ok.obj").indices.size(), 1u);
}

TEST_F(ObjStreaming, EmptyGroupNameIsAWarningWithItsLine) {
    write_text(m_dir / "g.obj",
               std::string(k_obj_quad) + "g \nf 1 2 3\n");  // "g" alone is no group
    const MeshData mesh = load_obj(m_dir / "g.obj");
    ASSERT_EQ(mesh.warnings.size(), 1u);
    EXPECT_EQ(mesh.warnings[0], (m_dir / "g.obj").string() + ":5: Empty group name");
}

TEST(ObjStreamingCancel, LoadingStopsWhenCancelled) {
    // In a child process: the cancel flag is process-wide and stays set.
    TempDir dir;
    write_text(dir / "big.obj", std::string(k_obj_quad) + repeated("f 1 2 3\n", 200000));
    const pid_t child = ::fork();
    if (child == 0) {
        request_cancel();
        try {
            load_obj(dir / "big.obj");
        } catch (const Interrupted&) {
            ::_exit(0);
        } catch (...) {
        }
        ::_exit(1);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "the load ran to its end";
}

}  // namespace
}  // namespace hikari
