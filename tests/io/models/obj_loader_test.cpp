#include "hikari/io/models/obj_loader.h"

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "../../support/expect_near.h"
#include "../../support/input_error.h"
#include "../../support/obj_text.h"
#include "../temp_dir.h"
#include "hikari/core/error.h"

namespace hikari {
namespace {

using testing::expect_near;
using testing::input_error_of;
using testing::k_obj_quad;
using testing::obj_load_error;
using testing::TempDir;
using testing::write_text;

TEST(ObjLoader, FaceIndicesAreParsedExactly) {
    // tinyobjloader reads indices with atoi: 2^32 + 3 would wrap to 3, "3abc" would be 3.
    TempDir dir;
    for (const char* corner : {"4294967299", "2147483648", "3abc", "12345678901234567890",
                               "-99999999999", "1/2/3/4", "2/", "+3", "1.5"}) {
        SCOPED_TRACE(corner);
        write_text(dir / "bad.obj",
                   std::string(k_obj_quad) + "vt 0 0\nvn 0 0 1\n\nf 1 2 " + corner + "\n");
        const std::string e = obj_load_error(dir / "bad.obj");
        EXPECT_NE(e.find("bad.obj:8: 'f': '" + std::string(corner) + "' is not a corner"),
                  std::string::npos)
            << e;
    }
    write_text(dir / "good.obj",
               std::string(k_obj_quad) + "vt 0 0\nvn 0 0 1\nf 1/1/1 2//1 -1/1 4\n");
    EXPECT_EQ(obj_load_error(dir / "good.obj"), "");
}

TEST(ObjLoader, IndexZeroIsExplained) {
    // A 0-based writer's mistake: the message says where OBJ indices start.
    TempDir dir;
    for (const char* corner : {"0", "1/0", "1//0", "-0"}) {
        SCOPED_TRACE(corner);
        write_text(dir / "zero.obj",
                   std::string(k_obj_quad) + "vt 0 0\nvn 0 0 1\n\nf 1 2 " + corner + "\n");
        const std::string e = obj_load_error(dir / "zero.obj");
        EXPECT_NE(e.find("zero.obj:8: 'f': '" + std::string(corner) +
                         "' uses index 0; OBJ indices start at 1"),
                  std::string::npos)
            << e;
    }
}

/// The colour `mesh` gives the vertex at `position` (every vertex there has the same one).
Vec3 colour_at(const MeshData& mesh, Vec3 position) {
    Vec3 found(-1.0f);
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        if (mesh.positions[i].x != position.x || mesh.positions[i].y != position.y ||
            mesh.positions[i].z != position.z)
            continue;
        if (found.x >= 0.0f)
            EXPECT_TRUE(found.x == mesh.colors[i].x && found.z == mesh.colors[i].z);
        found = mesh.colors[i];
    }
    return found;
}

TEST(ObjLoader, VertexColoursAreReadAndDecodedFromSrgb) {
    TempDir dir;
    // `v x y z r g b` (MeshLab's extension); the first vertex has none (white), the last one's
    // seventh number (alpha) is ignored, and a corner with a normal keeps its position's colour.
    write_text(dir / "c.obj",
               "v 0 0 0\nv 1 0 0 1 0 0\nv 1 1 0 0 0.5 1\nv 0 1 0 0 0 0 0.25\n"
               "vn 0 0 1\nf 1 2//1 3\nf 1 3 4\n");
    const MeshData mesh = load_obj(dir / "c.obj");
    ASSERT_EQ(mesh.colors.size(), mesh.positions.size());
    expect_near(colour_at(mesh, {0, 0, 0}), Vec3(1.0f), 0.0f);
    expect_near(colour_at(mesh, {1, 0, 0}), Vec3(1.0f, 0.0f, 0.0f), 0.0f);
    expect_near(colour_at(mesh, {1, 1, 0}), Vec3(0.0f, 0.21404f, 1.0f), 1e-5f);  // sRGB 0.5
    expect_near(colour_at(mesh, {0, 1, 0}), Vec3(0.0f), 0.0f);

    // Without colours there are none; `v x y z w` has a weight, not a colour.
    write_text(dir / "w.obj", "v 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\nf 1 2 3\n");
    EXPECT_TRUE(load_obj(dir / "w.obj").colors.empty());
}

TEST(ObjLoader, VertexColoursOutsideZeroToOneAreErrors) {
    TempDir dir;
    for (const char* bad : {"255 0 0", "0 -0.5 0", "0 0 nan"}) {
        write_text(dir / "c.obj", std::string("v 0 0 0\nv 1 0 0 ") + bad + "\nv 0 1 0\nf 1 2 3\n");
        const std::string e = obj_load_error(dir / "c.obj");
        EXPECT_EQ(e.rfind((dir / "c.obj").string() + ":2: 'v': ", 0), 0u) << bad << ": " << e;
    }
}

TEST(ObjLoader, QuadBecomesTwoTrianglesInOrder) {
    TempDir dir;
    write_text(dir / "quad.obj", std::string(k_obj_quad) + "f 1 2 3 4\n");
    const MeshData mesh = load_obj(dir / "quad.obj");
    ASSERT_EQ(mesh.indices.size(), 2u);
    ASSERT_EQ(mesh.positions.size(), 4u);
    // Fan from the first corner: (1 2 3), (1 3 4).
    auto position = [&](size_t t, int k) { return mesh.positions[mesh.indices[t][k]]; };
    expect_near(position(0, 0), {0, 0, 0}, 1e-6f);
    expect_near(position(0, 1), {1, 0, 0}, 1e-6f);
    expect_near(position(0, 2), {1, 1, 0}, 1e-6f);
    expect_near(position(1, 0), {0, 0, 0}, 1e-6f);
    expect_near(position(1, 1), {1, 1, 0}, 1e-6f);
    expect_near(position(1, 2), {0, 1, 0}, 1e-6f);
    EXPECT_TRUE(mesh.uvs.empty());
    EXPECT_EQ(mesh.degenerate_skipped, 0u);
}

TEST(ObjLoader, FanTrianglesFlagOnlyThePolygonOutline) {
    TempDir dir;
    // A pentagon fans into (1 2 3), (1 3 4), (1 4 5): edges 1–3 and 1–4 are diagonals.
    write_text(dir / "pent.obj", std::string(k_obj_quad) + "v 0.5 1.5 0\nf 1 2 3 5 4\nf 1 2 3\n");
    const MeshData mesh = load_obj(dir / "pent.obj");
    ASSERT_EQ(mesh.edge_flags.size(), 4u);
    EXPECT_EQ(mesh.edge_flags[0], 0b011);  // 1→2, 2→3 outline; 3→1 diagonal
    EXPECT_EQ(mesh.edge_flags[1], 0b010);  // 1→3 and 5→1 diagonals; 3→5 outline
    EXPECT_EQ(mesh.edge_flags[2], 0b110);  // 1→5 diagonal; 5→4, 4→1 outline
    EXPECT_EQ(mesh.edge_flags[3], 0b111);  // a triangle is its own outline
}

TEST(ObjLoader, EdgeFlagsStayWithTheirTrianglesWhenDegenerateOnesAreDropped) {
    TempDir dir;
    // The polygon's first fan triangle is degenerate (corners 1, 2, 5 collinear) and dropped:
    // the flags left are those of the second, (1 5 4).
    write_text(dir / "d.obj", std::string(k_obj_quad) + "v 2 0 0\nf 1 2 5 4\n");
    const MeshData mesh = load_obj(dir / "d.obj");
    ASSERT_EQ(mesh.indices.size(), 1u);
    ASSERT_EQ(mesh.edge_flags.size(), 1u);
    EXPECT_EQ(mesh.edge_flags[0], 0b110);  // 1→5 diagonal of the fan, 5→4 and 4→1 outline
}

TEST(ObjLoader, FlatQuadNormalsEqualFaceNormal) {
    TempDir dir;
    write_text(dir / "quad.obj", std::string(k_obj_quad) + "f 1 2 3 4\n");
    const MeshData mesh = load_obj(dir / "quad.obj");
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    for (const Vec3& n : mesh.normals) expect_near(n, {0, 0, 1}, 1e-6f);  // CCW from +z faces +z
}

TEST(ObjLoader, ClockwiseWindingFacesTheOtherWay) {
    TempDir dir;
    write_text(dir / "quad.obj", std::string(k_obj_quad) + "f 4 3 2 1\n");
    for (const Vec3& n : load_obj(dir / "quad.obj").normals) expect_near(n, {0, 0, -1}, 1e-6f);
}

TEST(ObjLoader, SmoothNormalsAverageAroundSharedPosition) {
    TempDir dir;
    // Two faces folded 90 degrees along the edge v1-v2, face normals +z and +x, each with a
    // right angle at v1: smoothed everywhere (crease angle 180), the normal there bisects them.
    write_text(dir / "fold.obj",
               "v 0 0 0\nv 0 1 0\nv 1 0 0\nv 0 0 1\n"
               "f 1 3 2\nf 1 2 4\n");
    const MeshData mesh = load_obj(dir / "fold.obj", {.crease_angle_degrees = 180});
    ASSERT_EQ(mesh.indices.size(), 2u);
    const Vec3 n_shared = mesh.normals[mesh.indices[0][0]];
    expect_near(n_shared, normalize(Vec3(1, 0, 1)), 1e-6f);
    expect_near(mesh.normals[mesh.indices[0][1]], {0, 0, 1},
                1e-6f);  // v3 only touches the first face
}

TEST(ObjLoader, SeamCornersShareSmoothNormal) {
    TempDir dir;
    // Same fold, but vertex 1 has different vt in the two faces: two output vertices, one normal.
    write_text(dir / "seam.obj",
               "v 0 0 0\nv 0 1 0\nv 1 0 0\nv 0 0 1\n"
               "vt 0 0\nvt 1 0\nvt 0 1\n"
               "f 1/1 3/2 2/3\nf 1/2 2/3 4/1\n");
    const MeshData mesh = load_obj(dir / "seam.obj", {.crease_angle_degrees = 180});
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    const uint32_t a = mesh.indices[0][0];
    const uint32_t b = mesh.indices[1][0];
    EXPECT_NE(a, b);
    EXPECT_EQ(mesh.positions[a], mesh.positions[b]);
    expect_near(mesh.normals[a], mesh.normals[b], 1e-6f);
    EXPECT_FLOAT_EQ(mesh.uvs[a].x, 0.0f);
    EXPECT_FLOAT_EQ(mesh.uvs[b].x, 1.0f);
}

TEST(ObjLoader, CornersMergeOnlyWithEqualIndicesNumberedByFirstUse) {
    TempDir dir;
    // Bare corners of one position share a vertex; a corner of the same position with a vt is
    // another vertex. Vertices are numbered in the order corners first name them.
    write_text(dir / "mix.obj",
               std::string(k_obj_quad) + "vt 0.5 0.5\nf 1 2 3\nf 2/1 3 4\nf 4 1 2/1\n");
    const MeshData mesh = load_obj(dir / "mix.obj");
    ASSERT_EQ(mesh.indices.size(), 3u);
    ASSERT_EQ(mesh.positions.size(), 5u);
    EXPECT_EQ(mesh.indices[0], (std::array<uint32_t, 3>{0, 1, 2}));
    EXPECT_EQ(mesh.indices[1], (std::array<uint32_t, 3>{3, 2, 4}));
    EXPECT_EQ(mesh.indices[2], (std::array<uint32_t, 3>{4, 0, 3}));
    EXPECT_EQ(mesh.positions[3], mesh.positions[1]);
    ASSERT_EQ(mesh.uvs.size(), 5u);
    EXPECT_FLOAT_EQ(mesh.uvs[3].x, 0.5f);
    EXPECT_FLOAT_EQ(mesh.uvs[1].x, 0.0f);  // a bare corner in a file with vt: (0, 0)
}

TEST(ObjLoader, GivenNormalsAreUsedAndNormalized) {
    TempDir dir;
    write_text(dir / "n.obj", std::string(k_obj_quad) +
                                  "vn 0 0 2\nvn 0 3 0\nvn 0 0 0\n"
                                  "f 1//1 2//2 3//3\n");
    const MeshData mesh = load_obj(dir / "n.obj");
    ASSERT_EQ(mesh.indices.size(), 1u);
    expect_near(mesh.normals[mesh.indices[0][0]], {0, 0, 1}, 1e-6f);
    expect_near(mesh.normals[mesh.indices[0][1]], {0, 1, 0}, 1e-6f);
    expect_near(mesh.normals[mesh.indices[0][2]], {0, 0, 1},
                1e-6f);  // zero normal: computed instead
}

TEST(ObjLoader, UsemtlMapsToMaterials) {
    TempDir dir;
    write_text(dir / "m.mtl",
               "newmtl red\nKa 0.1 0 0\nKd 0.8 0 0\nKs 0.5 0.5 0.5\nNs 32\n"
               "newmtl blue\nKd 0 0 0.7\nNi 1.5\nd 0.25\n");
    write_text(dir / "m.obj", std::string("mtllib m.mtl\n") + k_obj_quad +
                                  "f 1 2 3\n"
                                  "usemtl blue\nf 1 3 4\n"
                                  "usemtl red\nf 2 3 4 1\n");
    const MeshData mesh = load_obj(dir / "m.obj");
    ASSERT_EQ(mesh.materials.size(), 2u);
    ASSERT_EQ(mesh.material.size(), 4u);
    EXPECT_EQ(mesh.material[0], -1);
    const Material& blue = mesh.materials[mesh.material[1]];
    const Material& red = mesh.materials[mesh.material[2]];
    EXPECT_EQ(mesh.material[3], mesh.material[2]);
    EXPECT_EQ(red.name, "red");
    expect_near(red.ka, {0.1f, 0, 0}, 1e-6f);
    expect_near(red.kd, {0.8f, 0, 0}, 1e-6f);
    expect_near(red.ks, {0.5f, 0.5f, 0.5f}, 1e-6f);
    EXPECT_FLOAT_EQ(red.shininess, 32.0f);
    EXPECT_EQ(blue.name, "blue");
    expect_near(blue.kd, {0, 0, 0.7f}, 1e-6f);
    EXPECT_FLOAT_EQ(blue.ior, 1.5f);
    EXPECT_FLOAT_EQ(blue.transparency, 0.75f);
    EXPECT_EQ(blue.reflectivity, 0.0f);
    EXPECT_TRUE(mesh.warnings.empty());
}

TEST(ObjLoader, MtlIllumTrAndKeMapOntoTheMaterial) {
    TempDir dir;
    write_text(dir / "m.mtl",
               "newmtl mirror\nKd 0.1 0.1 0.1\nKs 0.9 0.6 0.3\nillum 3\n"
               "newmtl glass\nKd 0 0 0\nNi 1.45\nTr 0.9\nillum 7\nKs 0 0 0\n"
               "newmtl lamp\nKd 0 0 0\nKe 4 3 2\nillum 2\nKs 1 1 1\n");
    write_text(dir / "m.obj", std::string("mtllib m.mtl\n") + k_obj_quad +
                                  "usemtl mirror\nf 1 2 3\nusemtl glass\nf 1 3 4\n"
                                  "usemtl lamp\nf 2 3 4\n");
    const MeshData mesh = load_obj(dir / "m.obj");
    ASSERT_EQ(mesh.materials.size(), 3u);
    const Material& mirror = mesh.materials[mesh.material[0]];
    const Material& glass = mesh.materials[mesh.material[1]];
    const Material& lamp = mesh.materials[mesh.material[2]];
    EXPECT_FLOAT_EQ(mirror.reflectivity, 0.6f);  // illum 3: the mean of Ks
    EXPECT_FLOAT_EQ(glass.ior, 1.45f);
    EXPECT_NEAR(glass.transparency, 0.9f, 1e-6f);  // Tr = 1 - d
    EXPECT_EQ(lamp.reflectivity, 0.0f);            // illum 2: no ray-traced reflection
    expect_near(lamp.emission, {4, 3, 2}, 1e-6f);
}

TEST(ObjLoader, MtlInSubdirectoryIsRelativeToObj) {
    TempDir dir;
    std::filesystem::create_directories(dir / "models");
    write_text(dir / "models" / "m.mtl", "newmtl gold\nKd 1 0.8 0\n");
    write_text(dir / "models" / "m.obj",
               std::string("mtllib m.mtl\nusemtl gold\n") + k_obj_quad + "f 1 2 3\n");
    const MeshData mesh = load_obj(dir / "models" / "m.obj");
    ASSERT_EQ(mesh.materials.size(), 1u);
    EXPECT_EQ(mesh.material[0], 0);
}

TEST(ObjLoader, MissingMtlIsAWarning) {
    TempDir dir;
    write_text(dir / "m.obj",
               std::string("mtllib nowhere.mtl\nusemtl x\n") + k_obj_quad + "f 1 2 3\n");
    const MeshData mesh = load_obj(dir / "m.obj");
    EXPECT_EQ(mesh.material[0], -1);
    ASSERT_FALSE(mesh.warnings.empty());
    bool mentions_mtl = false;
    for (const std::string& w : mesh.warnings) {
        EXPECT_EQ(w.rfind((dir / "m.obj").string(), 0), 0u) << w;
        mentions_mtl |= w.find("nowhere.mtl") != std::string::npos;
    }
    EXPECT_TRUE(mentions_mtl);
}

TEST(ObjLoader, OutOfRangeTextureCoordinateNamesFileAndLine) {
    TempDir dir;
    write_text(dir / "bad.obj",
               std::string(k_obj_quad) + "vt 0 0\nvt 1 0\nf 1/1 2/2 3/1\nf 1/1 3/3 4/2\n");
    const std::string message = obj_load_error(dir / "bad.obj");
    EXPECT_EQ(message, (dir / "bad.obj").string() +
                           ":8: face refers to texture coordinate 3, but the file defines only 2");
}

TEST(ObjLoader, TextureCoordinatesFollowTheirCorners) {
    TempDir dir;
    write_text(dir / "uv.obj",
               std::string(k_obj_quad) + "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n");
    const MeshData mesh = load_obj(dir / "uv.obj");
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    for (size_t k = 0; k < mesh.positions.size(); ++k) {
        EXPECT_EQ(mesh.uvs[k].x, mesh.positions[k].x);
        EXPECT_EQ(mesh.uvs[k].y, mesh.positions[k].y);
    }
}

TEST(ObjLoader, OutOfRangeIndexNamesFileAndLine) {
    TempDir dir;
    write_text(dir / "bad.obj", std::string(k_obj_quad) + "f 1 2 3\nf 1 2 9\n");
    const std::string message = obj_load_error(dir / "bad.obj");
    EXPECT_EQ(message.rfind((dir / "bad.obj").string() + ":6: ", 0), 0u) << message;
    EXPECT_NE(message.find("vertex 9"), std::string::npos) << message;
}

TEST(ObjLoader, OutOfRangeRelativeAndNormalIndices) {
    TempDir dir;
    write_text(dir / "rel.obj", std::string(k_obj_quad) + "f -1 -2 -5\n");
    write_text(dir / "vn.obj", std::string(k_obj_quad) + "vn 0 0 1\nf 1//1 2//1 3//2\n");
    write_text(dir / "zero.obj", std::string(k_obj_quad) + "f 0 1 2\n");
    EXPECT_NE(obj_load_error(dir / "rel.obj").find("rel.obj:5: "), std::string::npos);
    EXPECT_NE(obj_load_error(dir / "vn.obj").find("vn.obj:6: face refers to normal 2"),
              std::string::npos)
        << obj_load_error(dir / "vn.obj");
    EXPECT_NE(obj_load_error(dir / "zero.obj").find("zero.obj:5: "), std::string::npos)
        << obj_load_error(dir / "zero.obj");
}

// Lines end at \n, \r\n or a lone \r (tinyobjloader's rule): the mesh and the line numbers of
// errors come out the same whichever the file uses, and an \r\n pair is one line end.
TEST(ObjLoader, LineEndingsAreLfCrLfOrLoneCr) {
    TempDir dir;
    write_text(dir / "mixed.obj", "v 0 0 0\r\nv 1 0 0\rv 1 1 0\nv 0 1 0\r\n\r\nf 1 2 3 4\r");
    const MeshData mesh = load_obj(dir / "mixed.obj");
    EXPECT_EQ(mesh.indices.size(), 2u);
    EXPECT_EQ(mesh.positions.size(), 4u);
    write_text(dir / "crlf.obj", "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\n\r\nf 1 2 9\r\n");
    write_text(dir / "cr.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\r\rf 1 2 9\r");
    write_text(dir / "number.obj", "v 0 0 0\r\nv 1 0 0\rv 0 x 0\nf 1 2 3\n");
    EXPECT_NE(obj_load_error(dir / "crlf.obj").find("crlf.obj:5: "), std::string::npos)
        << obj_load_error(dir / "crlf.obj");
    EXPECT_NE(obj_load_error(dir / "cr.obj").find("cr.obj:5: "), std::string::npos)
        << obj_load_error(dir / "cr.obj");
    EXPECT_NE(obj_load_error(dir / "number.obj").find("number.obj:3: 'v': 'x'"), std::string::npos)
        << obj_load_error(dir / "number.obj");
}

TEST(ObjLoader, MissingFileIsAnError) {
    TempDir dir;
    const std::string message = obj_load_error(dir / "missing.obj");
    EXPECT_EQ(message.rfind((dir / "missing.obj").string(), 0), 0u) << message;
    EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
}

TEST(ObjLoader, GarbageIsAnError) {
    TempDir dir;
    write_text(dir / "text.obj", "Lorem ipsum dolor sit amet\nconsectetur adipiscing elit\n");
    write_text(dir / "badnum.obj", "v 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n");
    write_text(dir / "nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n");
    write_text(dir / "short.obj", std::string(k_obj_quad) + "f 1 2\n");
    write_text(dir / "big.obj", "v 0 0 0\nv 1 0 0\nv 0 1e39 0\nf 1 2 3\n");  // float overflow
    EXPECT_NE(obj_load_error(dir / "text.obj").find("no faces"), std::string::npos);
    EXPECT_NE(obj_load_error(dir / "badnum.obj").find("badnum.obj:2: "), std::string::npos);
    EXPECT_NE(obj_load_error(dir / "nan.obj").find("nan.obj:3: "), std::string::npos);
    EXPECT_NE(obj_load_error(dir / "short.obj").find("short.obj:5: "), std::string::npos);
    EXPECT_NE(obj_load_error(dir / "big.obj").find("big.obj:3: "), std::string::npos);
}

TEST(ObjLoader, DegenerateTrianglesAreSkippedAndCounted) {
    TempDir dir;
    write_text(dir / "d.obj", std::string(k_obj_quad) +
                                  "v 2 0 0\n"
                                  "f 1 2 3\n"
                                  "f 1 2 5\n"  // collinear: zero area
                                  "f 1 1 3\n"  // repeated corner
                                  "f 1 3 4\n");
    const MeshData mesh = load_obj(dir / "d.obj");
    EXPECT_EQ(mesh.degenerate_skipped, 2u);
    ASSERT_EQ(mesh.indices.size(), 2u);
    EXPECT_EQ(mesh.positions[mesh.indices[1][2]], Vec3(0, 1, 0));  // the last face, now second
    EXPECT_EQ(mesh.material.size(), 2u);
}

TEST(ObjLoader, OnlyDegenerateTrianglesIsAnError) {
    TempDir dir;
    write_text(dir / "d.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
    EXPECT_NE(obj_load_error(dir / "d.obj").find("no usable triangles"), std::string::npos);
}

TEST(ObjLoader, GroupsKeepFileOrder) {
    TempDir dir;
    write_text(dir / "g.obj",
               std::string(k_obj_quad) + "g a\nf 1 2 3\no b\nf 1 3 4\ng c\nf 2 3 4\n");
    const MeshData mesh = load_obj(dir / "g.obj");
    ASSERT_EQ(mesh.indices.size(), 3u);
    EXPECT_EQ(mesh.positions[mesh.indices[0][1]], Vec3(1, 0, 0));
    EXPECT_EQ(mesh.positions[mesh.indices[1][2]], Vec3(0, 1, 0));
    EXPECT_EQ(mesh.positions[mesh.indices[2][0]], Vec3(1, 0, 0));
}

/// The message of the InputError that load_obj_triangles(path) throws, or "" when none.
std::string triangles_error(const std::filesystem::path& path) {
    return input_error_of([&] { load_obj_triangles(path); });
}

TEST(ObjTriangles, KeepsTheFilesNumbering) {
    // Every `v` in file order, used or not, and degenerate triangles kept: triangle i and
    // vertex k are the file's own, as the peer benchmarks number them.
    TempDir dir;
    write_text(dir / "m.obj",
               "v 9 9 9\n" + std::string(k_obj_quad) + "vn 0 0 1\nf 2//1 3//1 4//1\nf 2 3 3\n");
    const ObjTriangles mesh = load_obj_triangles(dir / "m.obj");
    ASSERT_EQ(mesh.positions.size(), 5u);
    EXPECT_EQ(mesh.positions[0], Vec3(9, 9, 9));
    EXPECT_EQ(mesh.indices, (std::vector<std::array<uint32_t, 3>>{{1, 2, 3}, {1, 2, 2}}));
}

TEST(ObjTriangles, QuadsSplitAsTinyobjloaderSplitsThem) {
    // Along the shorter diagonal: here 2-4, not 1-3 (a fan would use 1-3).
    TempDir dir;
    write_text(dir / "q.obj", "v 0 0 0\nv 1 0 0\nv 3 1 0\nv 0 1 0\nf 1 2 3 4\n");
    const ObjTriangles mesh = load_obj_triangles(dir / "q.obj");
    EXPECT_EQ(mesh.indices, (std::vector<std::array<uint32_t, 3>>{{0, 1, 3}, {1, 2, 3}}));
}

TEST(ObjTriangles, BadFilesAreErrorsNamingTheFile) {
    TempDir dir;
    const std::string missing = (dir / "missing.obj").string();
    EXPECT_EQ(triangles_error(missing).rfind(missing + ": cannot read", 0), 0u);
    write_text(dir / "points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    EXPECT_NE(triangles_error(dir / "points.obj").find(": no triangles"), std::string::npos);
    write_text(dir / "far.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n");
    EXPECT_NE(triangles_error(dir / "far.obj").find("triangle 2 refers to a vertex out of range"),
              std::string::npos);
    write_text(dir / "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n");
    EXPECT_NE(triangles_error(dir / "bad.obj").find("line 4"), std::string::npos);
}

}  // namespace
}  // namespace hikari
