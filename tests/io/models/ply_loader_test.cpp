#include "hikari/io/models/ply_loader.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <string>
#include <tuple>
#include <vector>

#include "../../support/input_error.h"
#include "../temp_dir.h"
#include "hikari/core/color.h"
#include "hikari/core/error.h"

namespace hikari {
namespace {

using testing::input_error_of;
using testing::TempDir;
using testing::write_text;

/// The message of the InputError that read_ply throws for `bytes` (named `name`), or "".
std::string ply_error(const std::string& bytes, const std::string& name = "bad.ply") {
    return input_error_of([&] { read_ply(name, bytes); });
}

/// Appends values in a chosen byte order, for binary bodies.
struct BinaryWriter {
    std::string bytes;
    bool big_endian = false;

    template <class T>
    BinaryWriter& put(T value) {
        std::array<char, sizeof(T)> raw = std::bit_cast<std::array<char, sizeof(T)>>(value);
        if (big_endian != (std::endian::native == std::endian::big))
            std::reverse(raw.begin(), raw.end());
        bytes.append(raw.data(), raw.size());
        return *this;
    }
};

/// A unit cube: 8 corners and 6 quads, counter-clockwise seen from outside.
constexpr std::array<std::array<float, 3>, 8> k_cube_positions = {
    {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
constexpr std::array<std::array<int, 4>, 6> k_cube_faces = {
    {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}}};

std::string cube_header(const std::string& format) {
    return "ply\nformat " + format +
           " 1.0\ncomment a cube\nelement vertex 8\nproperty float x\nproperty float y\n"
           "property float z\nelement face 6\nproperty list uchar int vertex_indices\n"
           "end_header\n";
}

std::string ascii_cube() {
    std::string text = cube_header("ascii");
    for (const auto& p : k_cube_positions)
        text +=
            std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
    for (const auto& f : k_cube_faces)
        text += "4 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " +
                std::to_string(f[2]) + " " + std::to_string(f[3]) + "\n";
    return text;
}

std::string binary_cube(bool big_endian) {
    BinaryWriter w{cube_header(big_endian ? "binary_big_endian" : "binary_little_endian"),
                   big_endian};
    for (const auto& p : k_cube_positions) w.put(p[0]).put(p[1]).put(p[2]);
    for (const auto& f : k_cube_faces) {
        w.put(uint8_t{4});
        for (int i : f) w.put(int32_t(i));
    }
    return w.bytes;
}

void expect_cube(const PolygonMesh& mesh) {
    ASSERT_EQ(mesh.positions.size(), 8u);
    for (size_t i = 0; i < 8; ++i) {
        EXPECT_EQ(mesh.positions[i].x, k_cube_positions[i][0]);
        EXPECT_EQ(mesh.positions[i].y, k_cube_positions[i][1]);
        EXPECT_EQ(mesh.positions[i].z, k_cube_positions[i][2]);
    }
    ASSERT_EQ(mesh.face_count(), 6u);
    for (size_t f = 0; f < 6; ++f) {
        ASSERT_EQ(mesh.face_start[f + 1] - mesh.face_start[f], 4u);
        for (size_t k = 0; k < 4; ++k)
            EXPECT_EQ(mesh.corners[mesh.face_start[f] + k], uint32_t(k_cube_faces[f][k]));
    }
    EXPECT_TRUE(mesh.normals.empty());
    EXPECT_TRUE(mesh.uvs.empty());
    EXPECT_TRUE(mesh.colors.empty());
    EXPECT_TRUE(mesh.warnings.empty());
}

TEST(PlyLoader, AsciiLittleAndBigEndianCubesAreTheSame) {
    const PolygonMesh ascii = read_ply("cube.ply", ascii_cube());
    const PolygonMesh little = read_ply("cube.ply", binary_cube(false));
    const PolygonMesh big = read_ply("cube.ply", binary_cube(true));
    expect_cube(ascii);
    expect_cube(little);
    expect_cube(big);
    // The ascii reader keeps each face's line for build_mesh's messages; the binary ones cannot.
    EXPECT_EQ(ascii.face_line, (std::vector<uint32_t>{19, 20, 21, 22, 23, 24}));
    EXPECT_TRUE(little.face_line.empty());
}

TEST(PlyLoader, EveryTypeIsReadInBothByteOrders) {
    // Positions of every PLY type, and faces with a ushort count and uchar indices: none of them
    // takes the fast paths.
    for (bool big_endian : {false, true}) {
        SCOPED_TRACE(big_endian);
        BinaryWriter w{std::string("ply\nformat ") +
                           (big_endian ? "binary_big_endian" : "binary_little_endian") +
                           " 1.0\nelement vertex 3\nproperty int8 x\nproperty uint16 y\n"
                           "property double z\nproperty uint confidence\nproperty short a\n"
                           "property int b\nelement face 1\n"
                           "property list ushort uchar vertex_index\nend_header\n",
                       big_endian};
        w.put(int8_t{-2}).put(uint16_t{60000}).put(0.25).put(uint32_t{7}).put(int16_t{-3});
        w.put(int32_t{-5});
        w.put(int8_t{1}).put(uint16_t{1}).put(-1.5).put(uint32_t{7}).put(int16_t{-3});
        w.put(int32_t{-5});
        w.put(int8_t{0}).put(uint16_t{2}).put(1e10).put(uint32_t{7}).put(int16_t{-3});
        w.put(int32_t{-5});
        w.put(uint16_t{3}).put(uint8_t{2}).put(uint8_t{1}).put(uint8_t{0});
        const PolygonMesh mesh = read_ply("types.ply", w.bytes);
        ASSERT_EQ(mesh.positions.size(), 3u);
        EXPECT_EQ(mesh.positions[0].x, -2.0f);
        EXPECT_EQ(mesh.positions[0].y, 60000.0f);
        EXPECT_EQ(mesh.positions[0].z, 0.25f);
        EXPECT_EQ(mesh.positions[1].z, -1.5f);
        EXPECT_EQ(mesh.positions[2].z, 1e10f);
        EXPECT_EQ(mesh.corners, (std::vector<uint32_t>{2, 1, 0}));
    }
}

TEST(PlyLoader, SkipsUnknownElementsAndProperties) {
    const std::string header_tail =
        " 1.0\nobj_info made by hand\nelement camera 2\nproperty float view_px\n"
        "property list uchar float stuff\n"
        "element vertex 3\nproperty float x\nproperty list uchar int links\nproperty float y\n"
        "property uchar quality\nproperty float z\n"
        "element face 1\nproperty uchar flags\nproperty list uchar int vertex_indices\n"
        "property list uint8 float32 texcoord\n"
        "element material 1\nproperty list int uchar name\nproperty double shine\nend_header\n";
    const std::string ascii = "ply\nformat ascii" + header_tail +
                              "1 2 5 6\n7 0\n"
                              "0 2 9 9 0 3 0\n1 0 0 4 0\n2 1 1 1 5 1\n"
                              "7 3 0 1 2 6 0 0 1 0 1 1\n3 104 105 33 0.5\n";
    BinaryWriter w{"ply\nformat binary_little_endian" + header_tail};
    w.put(1.0f).put(uint8_t{2}).put(5.0f).put(6.0f);
    w.put(7.0f).put(uint8_t{0});
    w.put(0.0f).put(uint8_t{2}).put(9).put(9).put(0.0f).put(uint8_t{3}).put(0.0f);
    w.put(1.0f).put(uint8_t{0}).put(0.0f).put(uint8_t{4}).put(0.0f);
    w.put(2.0f).put(uint8_t{1}).put(1).put(1.0f).put(uint8_t{5}).put(1.0f);
    w.put(uint8_t{7}).put(uint8_t{3}).put(0).put(1).put(2);
    w.put(uint8_t{6}).put(0.0f).put(0.0f).put(1.0f).put(0.0f).put(1.0f).put(1.0f);
    w.put(int32_t{3}).put(uint8_t{104}).put(uint8_t{105}).put(uint8_t{33}).put(0.5);
    for (const std::string& bytes : {ascii, w.bytes}) {
        const PolygonMesh mesh = read_ply("skip.ply", bytes);
        ASSERT_EQ(mesh.positions.size(), 3u);
        EXPECT_EQ(mesh.positions[0].y, 0.0f);
        EXPECT_EQ(mesh.positions[1].x, 1.0f);
        EXPECT_EQ(mesh.positions[2].x, 2.0f);
        EXPECT_EQ(mesh.positions[2].y, 1.0f);
        EXPECT_EQ(mesh.positions[2].z, 1.0f);
        EXPECT_EQ(mesh.corners, (std::vector<uint32_t>{0, 1, 2}));
        EXPECT_TRUE(mesh.warnings.empty()) << mesh.warnings[0];
    }
}

TEST(PlyLoader, ReadsNormalsTextureCoordinatesAndColours) {
    const std::string text =
        "ply\r\nformat ascii 1.0\r\nelement vertex 3\r\nproperty float x\r\nproperty float y\r\n"
        "property float z\r\nproperty float nx\r\nproperty float ny\r\nproperty float nz\r\n"
        "property float texture_u\r\nproperty float texture_v\r\nproperty uchar red\r\n"
        "property uchar green\r\nproperty uchar blue\r\nproperty uchar alpha\r\n"
        "element face 1\r\nproperty list uchar uint vertex_indices\r\nend_header\r\n"
        "0 0 0 0 0 1 0.25 0.75 255 0 128 7\r\n"
        "1 0 0 0 0 2 1 0 0 255 0 7\r\n"
        "0 1 0 0 1 0 0 1 10 20 30 7\r\n"
        "3 0 1 2\r\n";
    const PolygonMesh mesh = read_ply("attributes.ply", text);
    ASSERT_EQ(mesh.normals.size(), 3u);
    EXPECT_EQ(mesh.normals[1].z, 2.0f);  // as the file gives it: build_mesh normalizes
    EXPECT_EQ(mesh.normals[2].y, 1.0f);
    ASSERT_EQ(mesh.uvs.size(), 3u);
    EXPECT_EQ(mesh.uvs[0].x, 0.25f);
    EXPECT_EQ(mesh.uvs[0].y, 0.75f);
    ASSERT_EQ(mesh.colors.size(), 3u);
    // 8-bit colours are sRGB-encoded: 128 is about 0.216 in linear light, not 0.5.
    EXPECT_EQ(mesh.colors[0].x, 1.0f);
    EXPECT_EQ(mesh.colors[0].y, 0.0f);
    EXPECT_NEAR(mesh.colors[0].z, 0.2158605f, 1e-6f);
    EXPECT_EQ(mesh.colors[1].y, 1.0f);
    EXPECT_NEAR(mesh.colors[2].z, srgb_to_linear(30.0f / 255.0f), 1e-7f);

    // Float colours are linear already; s/t name texture coordinates too.
    const std::string floats =
        "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
        "property float z\nproperty float s\nproperty float t\nproperty float red\n"
        "property float green\nproperty float blue\nend_header\n0 0 0 0.5 0.125 0.5 0.25 1\n";
    const PolygonMesh linear = read_ply("floats.ply", floats);
    ASSERT_EQ(linear.colors.size(), 1u);
    EXPECT_EQ(linear.colors[0].x, 0.5f);
    EXPECT_EQ(linear.colors[0].y, 0.25f);
    ASSERT_EQ(linear.uvs.size(), 1u);
    EXPECT_EQ(linear.uvs[0].y, 0.125f);
}

TEST(PlyLoader, PartialNormalsAreIgnoredWithAWarning) {
    const std::string text =
        "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
        "property float z\nproperty float nx\nproperty float ny\nend_header\n0 0 0 1 0\n";
    const PolygonMesh mesh = read_ply("partial.ply", text);
    EXPECT_TRUE(mesh.normals.empty());
    ASSERT_EQ(mesh.warnings.size(), 1u);
    EXPECT_NE(mesh.warnings[0].find("partial.ply:3: vertex has only some of nx, ny, nz"),
              std::string::npos)
        << mesh.warnings[0];
}

TEST(PlyLoader, KeepsQuadsAndConcavePolygonsWhole) {
    // An L-shaped (concave) hexagon and a quad: triangulating them is build_mesh's job.
    const std::string text =
        "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
        "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n2 0 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\n3 0 0\n3 1 0\n"
        "6 0 1 2 3 4 5\n4 1 6 7 2\n";
    const PolygonMesh mesh = read_ply("polygons.ply", text);
    EXPECT_EQ(mesh.face_start, (std::vector<uint32_t>{0, 6, 10}));
    EXPECT_EQ(mesh.corners, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5, 1, 6, 7, 2}));
}

/// The z component of the normal (P1 - P0) x (P2 - P0) of face f, for a mesh in the z = 0 plane.
float face_normal_z(const PolygonMesh& mesh, size_t f) {
    const Vec3 a = mesh.positions[mesh.corners[mesh.face_start[f]]];
    const Vec3 b = mesh.positions[mesh.corners[mesh.face_start[f] + 1]];
    const Vec3 c = mesh.positions[mesh.corners[mesh.face_start[f] + 2]];
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

TEST(PlyLoader, TristripsKeepTheStripsOrientation) {
    // A zig-zag strip of 4 triangles facing +z, then -1 and a second strip of one triangle, and
    // a repeated index (a join between strips) that makes two degenerate triangles to skip.
    const std::string header =
        "element vertex 6\nproperty float x\nproperty float y\nproperty float z\n"
        "element tristrips 1\nproperty list int int vertex_indices\nend_header\n";
    const std::string positions = "0 0 0\n0 1 0\n1 0 0\n1 1 0\n2 0 0\n2 1 0\n";
    const std::vector<int> strip = {0, 2, 1, 3, 3, 2, 5, 4, -1, 0, 2, 1};
    std::string text =
        "ply\nformat ascii 1.0\n" + header + positions + std::to_string(strip.size());
    for (int i : strip) text += " " + std::to_string(i);
    BinaryWriter w{"ply\nformat binary_big_endian 1.0\n" + header, true};
    for (float v : {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 2, 0, 0, 2, 1, 0}) w.put(v);
    w.put(int32_t(strip.size()));
    for (int i : strip) w.put(int32_t{i});

    for (const std::string& bytes : {text + "\n", w.bytes}) {
        const PolygonMesh mesh = read_ply("strip.ply", bytes);
        // Strip triangles (0 2 1), (2 1 3) odd so (1 2 3), (1 3 3) and (3 3 2) skipped, (3 2 5),
        // (2 5 4) odd so (5 2 4); then the second strip's (0 2 1).
        ASSERT_EQ(mesh.face_count(), 5u);
        EXPECT_EQ(mesh.corners,
                  (std::vector<uint32_t>{0, 2, 1, 1, 2, 3, 3, 2, 5, 5, 2, 4, 0, 2, 1}));
        for (size_t f = 0; f < mesh.face_count(); ++f) {
            EXPECT_EQ(mesh.face_start[f + 1] - mesh.face_start[f], 3u);
            EXPECT_GT(face_normal_z(mesh, f), 0.0f) << "face " << f;
        }
    }
}

/// A small ascii mesh with `body` as its body: 3 vertices at lines 11-13, faces from line 14.
std::string ascii_triangle(const std::string& body, int faces = 1) {
    return "ply\nformat ascii 1.0\ncomment test\nelement vertex 3\nproperty float x\n"
           "property float y\nproperty float z\nelement face " +
           std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n" + body;
}

TEST(PlyLoader, MalformedHeadersNameTheLine) {
    const std::string vertex = "element vertex 3\nproperty float x\nproperty float y\n";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"plx\nformat ascii 1.0\nend_header\n", "bad.ply:1: not a PLY file"},
        {"", "bad.ply:1: not a PLY file"},
        {"ply", "bad.ply:1: the file ends inside the header"},
        {"ply\nformat ascii 1.0\n" + vertex, "bad.ply:5: the file ends inside the header"},
        {"ply\nformat ascii 2.0\nend_header\n", "bad.ply:2: expected 'format"},
        {"ply\nformat binary_middle_endian 1.0\nend_header\n", "bad.ply:2: unknown format"},
        {"ply\nformat ascii 1.0\nformat ascii 1.0\nend_header\n", "bad.ply:3: a second 'format'"},
        {"ply\nelement vertex 3\nend_header\n", "bad.ply:2: 'element' before the 'format'"},
        {"ply\ncomment\nend_header\n", "bad.ply:3: the header has no 'format' line"},
        {"ply\nformat ascii 1.0\nelement vertex 1e3\nend_header\n",
         "bad.ply:3: element count '1e3' is not a whole number"},
        {"ply\nformat ascii 1.0\nelement vertex -1\nend_header\n", "bad.ply:3: element count '-1'"},
        {"ply\nformat ascii 1.0\nelement vertex +1\nend_header\n", "bad.ply:3: element count '+1'"},
        {"ply\nformat ascii 1.0\nelement vertex 12abc\nend_header\n",
         "bad.ply:3: element count '12abc'"},
        {"ply\nformat ascii 1.0\nelement vertex 18446744073709551616\nend_header\n",
         "bad.ply:3: element count '18446744073709551616'"},
        {"ply\nformat ascii 1.0\nelement vertex\nend_header\n", "bad.ply:3: expected 'element"},
        {"ply\nformat ascii 1.0\nproperty float x\nend_header\n",
         "bad.ply:3: 'property' before any element"},
        {"ply\nformat ascii 1.0\n" + vertex + "property flt z\nend_header\n",
         "bad.ply:6: unknown property type 'flt'"},
        {"ply\nformat ascii 1.0\n" + vertex + "property float y\nend_header\n",
         "bad.ply:6: a second property 'y'"},
        {"ply\nformat ascii 1.0\n" + vertex + "property list float int z\nend_header\n",
         "bad.ply:6: a list's length must have an integer type"},
        {"ply\nformat ascii 1.0\n" + vertex + "property list uchar int\nend_header\n",
         "bad.ply:6: expected 'property TYPE NAME'"},
        {"ply\nformat ascii 1.0\n" + vertex + "end_header\n",
         "bad.ply:3: element 'vertex' has no property 'z'"},
        {"ply\nformat ascii 1.0\n" + vertex + "property list uchar float z\nend_header\n",
         "bad.ply:3: vertex property 'z' is a list"},
        {"ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int vertex_indices\n"
         "end_header\n",
         "bad.ply:5: the header declares no 'vertex' element"},
        {ascii_triangle("").replace(ascii_triangle("").find("list uchar int vertex_indices"), 29,
                                    "uchar vertex_indices"),
         "bad.ply:8: 'vertex_indices' of element 'face' must be a list of integers"},
        {ascii_triangle("").replace(ascii_triangle("").find("vertex_indices"), 14, "corners"),
         "bad.ply:8: element 'face' has no list property 'vertex_indices'"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nelement vertex 1\nend_header\n",
         "bad.ply:4: a second element 'vertex'"},
    };
    for (const auto& [bytes, expected] : cases) {
        SCOPED_TRACE(bytes);
        const std::string e = ply_error(bytes);
        EXPECT_NE(e.find(expected), std::string::npos) << e;
    }
}

TEST(PlyLoader, MalformedAsciiBodiesNameTheLineAndItem) {
    const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {ascii_triangle("0 0 0\n1 abc 0\n0 1 0\n3 0 1 2\n"),
         "bad.ply:12: vertex 1: 'abc' is not a number"},
        {ascii_triangle("0 0 0\n1 0 0\n0 1 nan\n"), "bad.ply:13: vertex 2: position (0, 1, nan)"},
        {ascii_triangle("0 0 0\n1 0 0\n0 1 1e39\n"),
         "bad.ply:13: vertex 2: 1e39 is too large for a 32-bit float"},
        {ascii_triangle("0 0 0\n1 0 0\n0 1 -1e400\n"),
         "bad.ply:13: vertex 2: -1e400 is too large for a 32-bit float"},
        {ascii_triangle(vertices + "3 0 1 2\n2 0 1\n", 2),
         "bad.ply:15: face 1: it has 2 corners; a face needs 3 to 255"},
        {ascii_triangle(vertices + "3 0 1 3\n"),
         "bad.ply:14: face 0: corner index 3 is out of range (the file has 3 vertices)"},
        {ascii_triangle(vertices + "3 0 -1 2\n"), "bad.ply:14: face 0: corner index -1"},
        {ascii_triangle(vertices + "3 0 1.5 2\n"), "bad.ply:14: face 0: '1.5' is not a whole"},
        {ascii_triangle(vertices + "3 0 99999999999 2\n"),
         "bad.ply:14: face 0: '99999999999' is not a whole number of type int"},
        {ascii_triangle(vertices + "256 0 1 2\n"), "bad.ply:14: face 0: '256' is not a whole"},
        {ascii_triangle(vertices + "-1 0 1 2\n"), "bad.ply:14: face 0: '-1' is not a whole"},
        {ascii_triangle(vertices + "200 0 1 2\n"),
         "bad.ply:14: face 0: list 'vertex_indices' has length 200, more than the rest"},
        {ascii_triangle(vertices + "3 0 1\n"), "bad.ply:14: face 0: the file ends in the middle"},
        {ascii_triangle(vertices), "bad.ply:8: element 'face' declares 1 items, more than"},
    };
    for (const auto& [bytes, expected] : cases) {
        SCOPED_TRACE(bytes);
        const std::string e = ply_error(bytes);
        EXPECT_NE(e.find(expected), std::string::npos) << e;
    }
}

TEST(PlyLoader, MalformedBinaryBodiesNameTheByte) {
    const std::string cube = binary_cube(false);
    const size_t body = cube.find("end_header\n") + 11;
    const size_t faces = body + 8 * 12;  // where the faces start
    // Truncated inside the vertices and inside the last face.
    EXPECT_NE(
        ply_error(cube.substr(0, body + 20)).find("bad.ply:4: element 'vertex' declares 8 items"),
        std::string::npos);
    std::string e = ply_error(cube.substr(0, cube.size() - 2));
    EXPECT_NE(e.find(fmt::format("bad.ply: byte {}: face 5: the file ends", faces + 5 * 17)),
              std::string::npos)
        << e;
    // A face of 2 corners, a corner out of range, a huge list length.
    std::string two = cube;
    two[faces + 17] = 2;
    e = ply_error(two);
    EXPECT_NE(e.find(fmt::format("bad.ply: byte {}: face 1: it has 2 corners", faces + 17)),
              std::string::npos)
        << e;
    std::string far = cube;
    far[faces + 17 + 1 + 4] = 8;
    e = ply_error(far);
    EXPECT_NE(
        e.find(fmt::format("bad.ply: byte {}: face 1: corner index 8 is out of range", faces + 17)),
        std::string::npos)
        << e;
    std::string negative = cube;
    std::memset(&negative[faces + 1], 0xff, 4);
    e = ply_error(negative);
    EXPECT_NE(e.find("face 0: corner index -1 is out of range"), std::string::npos) << e;
    std::string huge = cube;
    huge[faces + 5 * 17] = char(200);
    e = ply_error(huge);
    EXPECT_NE(e.find(fmt::format("bad.ply: byte {}: face 5: the file ends", faces + 5 * 17)),
              std::string::npos)
        << e;
    // A non-finite position.
    std::string nan = cube;
    const float not_a_number = std::nanf("");
    std::memcpy(&nan[body + 3 * 12 + 4], &not_a_number, 4);
    e = ply_error(nan);
    EXPECT_NE(e.find(fmt::format("bad.ply: byte {}: vertex 3: position", body + 36)),
              std::string::npos)
        << e;
}

/// A binary strip of n × 1 quads as triangles: 2 (n + 1) vertices, 2 n faces.
std::string binary_strip(int n) {
    BinaryWriter w{
        fmt::format("ply\nformat binary_little_endian 1.0\nelement vertex {}\n"
                    "property float x\nproperty float y\nproperty float z\n"
                    "element face {}\nproperty list uchar int vertex_indices\n"
                    "end_header\n",
                    2 * (n + 1), 2 * n)};
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j < 2; ++j) w.put(float(i)).put(float(j)).put(0.01f * float(i % 7));
    for (int i = 0; i < n; ++i) {
        w.put(uint8_t{3}).put(2 * i).put(2 * i + 2).put(2 * i + 3);
        w.put(uint8_t{3}).put(2 * i).put(2 * i + 3).put(2 * i + 1);
    }
    return w.bytes;
}

TEST(PlyLoader, BinaryBodiesReadTheSameOnOneThreadAsOnAll) {
    // vertices and faces are copied and checked in parallel chunks
    const std::string bytes = binary_strip(100000);
    PolygonMesh one;
    {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = read_ply("strip.ply", bytes);
    }
    const PolygonMesh all = read_ply("strip.ply", bytes);
    EXPECT_EQ(one.positions, all.positions);
    EXPECT_EQ(one.corners, all.corners);
    EXPECT_EQ(one.face_start, all.face_start);
    ASSERT_EQ(all.face_count(), 200000u);
    // face 150001 is the second of quad 75000: corners 150000, 150003, 150001
    EXPECT_EQ(all.corners[3 * 150001 + 2], 150001u);
}

TEST(PlyLoader, TheFirstBadItemOfABinaryBodyIsReported) {
    // a bad index in a late chunk, another in an early one, and a face of two corners after
    // both: the error is the earliest in the file, as a reader going face by face finds it
    const std::string good = binary_strip(100000);
    const size_t body = good.find("end_header\n") + 11;
    const size_t faces = body + 200002 * 12;
    auto corrupt = [&](std::string bytes, size_t face, int corner, int value) {
        std::memcpy(&bytes[faces + 13 * face + 1 + 4 * corner], &value, 4);
        return bytes;
    };
    std::string bad = corrupt(corrupt(good, 190000, 1, 500000), 70000, 2, -4);
    std::string e = ply_error(bad);
    EXPECT_NE(e.find(fmt::format("byte {}: face 70000: corner index -4", faces + 13 * 70000)),
              std::string::npos)
        << e;
    bad[faces + 13 * 180000] = 2;
    e = ply_error(bad);
    EXPECT_NE(e.find("face 70000: corner index -4"), std::string::npos) << e;
    std::string two = good;
    two[faces + 13 * 180000] = 2;
    e = ply_error(two);
    EXPECT_NE(e.find("face 180000: it has 2 corners"), std::string::npos) << e;
    // the first non-finite vertex of several
    std::string nan = good;
    const float not_a_number = std::nanf("");
    std::memcpy(&nan[body + 150000 * 12], &not_a_number, 4);
    std::memcpy(&nan[body + 90000 * 12 + 8], &not_a_number, 4);
    e = ply_error(nan);
    EXPECT_NE(e.find("vertex 90000: position"), std::string::npos) << e;
}

TEST(PlyLoader, BadListLengthsInTheGenericBinaryPath) {
    // A signed count type (-3) and a uint count larger than the file, in big-endian (no fast path).
    for (const auto& [count_type, count, expected] :
         std::vector<std::tuple<std::string, int64_t, std::string>>{
             {"char", -3, "has a negative length -3"},
             {"uint", 4000000000, "has length 4000000000"}}) {
        BinaryWriter w{
            "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\n"
            "property float y\nproperty float z\nelement face 1\nproperty list " +
                count_type + " int vertex_indices\nend_header\n",
            true};
        for (int i = 0; i < 9; ++i) w.put(float(i));
        const size_t face = w.bytes.size();
        if (count_type == "char")
            w.put(int8_t(count));
        else
            w.put(uint32_t(count));
        w.put(0).put(1).put(2);
        const std::string e = ply_error(w.bytes);
        EXPECT_NE(e.find(fmt::format("bad.ply: byte {}: face 0: list 'vertex_indices' {}", face,
                                     expected)),
                  std::string::npos)
            << e;
    }
}

TEST(PlyLoader, AbsurdCountsAreRefusedBeforeReading) {
    // A trillion vertices would need 12 TB of floats: refused at the header, nothing allocated.
    const std::string tail = "property float x\nproperty float y\nproperty float z\nend_header\n";
    for (const std::string format : {"ascii", "binary_little_endian"}) {
        const std::string e = ply_error("ply\nformat " + format +
                                        " 1.0\nelement vertex 1000000000000\n" + tail + "0 0 0\n");
        EXPECT_NE(e.find("bad.ply:3: element 'vertex' declares 1000000000000 items, more than "
                         "the 6 bytes after the header can hold"),
                  std::string::npos)
            << e;
    }
    // Each element is counted against what the ones before it leave.
    const std::string faces = ply_error(ascii_triangle("0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", 1000));
    EXPECT_NE(faces.find("bad.ply:8: element 'face' declares 1000"), std::string::npos) << faces;
    // An element of no properties takes no bytes, whatever its count, and is skipped at once.
    const PolygonMesh mesh =
        read_ply("empty.ply", ascii_cube().insert(ascii_cube().find("end_header"),
                                                  "element nothing 18446744073709551615\n"));
    expect_cube(mesh);
}

TEST(PlyLoader, TrailingDataIsAWarning) {
    const PolygonMesh ascii = read_ply("more.ply", ascii_cube() + "\n\n1 2 3\n");
    ASSERT_EQ(ascii.warnings.size(), 1u);
    EXPECT_EQ(ascii.warnings[0], "more.ply:27: text after the last element is ignored");
    const std::string binary = binary_cube(false);
    const PolygonMesh little = read_ply("more.ply", binary + "xyz");
    ASSERT_EQ(little.warnings.size(), 1u);
    EXPECT_EQ(little.warnings[0],
              fmt::format("more.ply: byte {}: 3 bytes after the last element are ignored",
                          binary.size()));
    EXPECT_TRUE(read_ply("cube.ply", ascii_cube() + "\n \n").warnings.empty());
}

TEST(PlyLoader, UnknownHeaderLinesAreWarnings) {
    // Blender 2.47's exporter writes a free-text line without `comment`.
    std::string text = ascii_cube();
    text.insert(text.find("comment"), "Created by Blender3D 247 - www.blender.org\n");
    const PolygonMesh mesh = read_ply("blender.ply", text);
    ASSERT_EQ(mesh.warnings.size(), 1u);
    EXPECT_NE(mesh.warnings[0].find("blender.ply:3: unknown header line ignored"),
              std::string::npos);
    EXPECT_EQ(mesh.positions.size(), 8u);
    // Only the first is named: a header of a million such lines must not make a million warnings.
    text.insert(text.find("end_header"), "junk\nmore junk\n");
    const PolygonMesh junk = read_ply("junk.ply", text);
    ASSERT_EQ(junk.warnings.size(), 2u);
    EXPECT_EQ(junk.warnings[1], "junk.ply: 2 more unknown header lines ignored");
}

TEST(PlyLoader, LoadPlyBuildsTheTriangleMesh) {
    TempDir dir;
    write_text(dir / "cube.ply", binary_cube(true));
    const MeshData mesh = load_ply(dir / "cube.ply");
    EXPECT_EQ(mesh.indices.size(), 12u);
    EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
    write_text(dir / "bad.ply", "ply\nformat ascii 1.0\nelement vertex 1\nend_header\n");
    try {
        load_ply(dir / "bad.ply");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find((dir / "bad.ply").string() + ":3: element 'vertex' "
                                                                          "has no property 'x'"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(load_ply(dir / "missing.ply"), InputError);
}

}  // namespace
}  // namespace hikari
