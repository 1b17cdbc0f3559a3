#include "hikari/io/models/mesh_builder.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <bit>
#include <cmath>
#include <fstream>

#include "../../support/input_error.h"
#include "../temp_dir.h"
#include "hikari/core/error.h"
#include "hikari/io/models/obj_loader.h"

namespace hikari {
namespace {

using testing::input_error_of;

/// A unit cube of 8 shared corners and 6 quads, counter-clockwise from outside, no normals.
PolygonMesh cube() {
    PolygonMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                   {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    m.add_face({0, 3, 2, 1});  // z = 0
    m.add_face({4, 5, 6, 7});  // z = 1
    m.add_face({0, 1, 5, 4});  // y = 0
    m.add_face({3, 7, 6, 2});  // y = 1
    m.add_face({0, 4, 7, 3});  // x = 0
    m.add_face({1, 2, 6, 5});  // x = 1
    return m;
}

/// The face normal of triangle t.
Vec3 face_normal(const MeshData& m, size_t t) {
    const auto& i = m.indices[t];
    return normalize(
        cross(m.positions[i[1]] - m.positions[i[0]], m.positions[i[2]] - m.positions[i[1]]));
}

TEST(MeshBuilder, FloodsOfOneTriangleKeepOneCopy) {
    // 200 copies of one triangle (some turned to start at another corner), 200 of it wound the
    // other way, 200 with another material: one of each is kept, in file order, and the count
    // of the others is a warning. A triangle repeated a few times at vertices few triangles share
    // is left alone.
    PolygonMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}};
    m.materials.resize(2);
    for (int copy = 0; copy < 200; ++copy) {
        m.add_face(copy % 3 == 0 ? std::initializer_list<uint32_t>{1, 2, 0}
                                 : std::initializer_list<uint32_t>{0, 1, 2});
        m.face_material.push_back(0);
        m.add_face({0, 2, 1});
        m.face_material.push_back(0);
        m.add_face({0, 1, 2});
        m.face_material.push_back(1);
    }
    for (int copy = 0; copy < 3; ++copy) {
        m.add_face({3, 4, 5});
        m.face_material.push_back(0);
    }
    const MeshData mesh = build_mesh("flood.obj", m);
    ASSERT_EQ(mesh.indices.size(), 6u);
    EXPECT_EQ(mesh.material[0], 0);
    EXPECT_EQ(mesh.material[2], 1);
    EXPECT_EQ(mesh.material[5], 0);
    ASSERT_EQ(mesh.warnings.size(), 1u);
    EXPECT_EQ(mesh.warnings[0],
              "flood.obj: skipped 597 repeated triangle(s) (the same corners and "
              "material as an earlier one)");
}

TEST(MeshBuilder, CubeWithoutNormalsHasFlatFacesAndSharpEdges) {
    const MeshData m = build_mesh("cube.obj", cube());
    ASSERT_EQ(m.indices.size(), 12u);
    EXPECT_EQ(m.positions.size(), 24u);  // each corner split three ways along the creases
    for (size_t t = 0; t < m.indices.size(); ++t)
        for (uint32_t v : m.indices[t]) {
            const Vec3 n = m.normals[v];
            EXPECT_NEAR(dot(n, face_normal(m, t)), 1.0f, 1e-6f);
        }
}

TEST(MeshBuilder, CreaseAngleOf180SmoothsEverything) {
    const MeshData m = build_mesh("cube.obj", cube(), {.crease_angle_degrees = 180});
    EXPECT_EQ(m.positions.size(), 8u);
    for (size_t v = 0; v < m.positions.size(); ++v) {
        // Each corner's normal points out along the diagonal from the centre.
        const Vec3 out = normalize(m.positions[v] - Vec3(0.5f));
        EXPECT_NEAR(dot(m.normals[v], out), 1.0f, 1e-5f);
    }
}

/// A gently curved strip: a row of quads bent 10 degrees at each shared edge.
PolygonMesh bent_strip(int quads, float bend_degrees) {
    PolygonMesh m;
    float angle = 0, x = 0, z = 0;
    for (int k = 0; k <= quads; ++k) {
        m.positions.push_back({x, 0, z});
        m.positions.push_back({x, 1, z});
        x += std::cos(angle);
        z -= std::sin(angle);
        angle += bend_degrees * float(M_PI) / 180.0f;
    }
    for (int k = 0; k < quads; ++k) {
        const auto a = uint32_t(2 * k);
        m.add_face({a, a + 2, a + 3, a + 1});
    }
    return m;
}

TEST(MeshBuilder, EdgesBelowTheCreaseAngleStaySmooth) {
    const MeshData smooth =
        build_mesh("strip.ply", bent_strip(6, 10), {.crease_angle_degrees = 45});
    EXPECT_EQ(smooth.positions.size(), 14u);  // no vertex split
    const MeshData flat = build_mesh("strip.ply", bent_strip(6, 10), {.crease_angle_degrees = 5});
    EXPECT_EQ(flat.positions.size(), 24u);  // every shared edge split
    const MeshData faceted =
        build_mesh("strip.ply", bent_strip(6, 10), {.crease_angle_degrees = 0});
    for (size_t t = 0; t < faceted.indices.size(); ++t)
        for (uint32_t v : faceted.indices[t])
            EXPECT_NEAR(dot(faceted.normals[v], face_normal(faceted, t)), 1.0f, 1e-6f);
}

TEST(MeshBuilder, SmoothingGroupsDecideOverTheCreaseAngle) {
    PolygonMesh m = cube();
    // The four side faces in group 1, top and bottom off: the sides round into a cylinder-like
    // shading although they meet at 90 degrees; top and bottom stay flat.
    m.smoothing_group = {0, 0, 1, 1, 1, 1};
    const MeshData out = build_mesh("cube.obj", m);
    for (size_t t = 0; t < out.indices.size(); ++t) {
        const Vec3 f = face_normal(out, t);
        for (uint32_t v : out.indices[t]) {
            if (std::abs(f.z) > 0.5f) {
                EXPECT_NEAR(dot(out.normals[v], f), 1.0f, 1e-6f);
            } else {
                // Averaged with the neighbouring side: halfway, both faces meeting at 90°.
                EXPECT_NEAR(out.normals[v].z, 0.0f, 1e-6f);
                EXPECT_NEAR(dot(out.normals[v], f), std::sqrt(0.5f), 1e-5f);
            }
        }
    }
}

TEST(MeshBuilder, FileNormalsAreKept) {
    PolygonMesh m = cube();
    m.normals.assign(8, Vec3{0, 0, 2});
    m.normals[0] = Vec3(0.0f);  // unusable: made as if absent
    const MeshData out = build_mesh("cube.obj", m);
    for (size_t v = 0; v < out.positions.size(); ++v) {
        if (out.positions[v] == Vec3(0.0f)) continue;
        EXPECT_EQ(out.normals[v], (Vec3{0, 0, 1}));
    }
}

TEST(MeshBuilder, ConcaveFaceIsEarClippedAndKeepsItsOutline) {
    PolygonMesh m;
    m.positions = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
    m.add_face({3, 4, 5, 0, 1, 2});  // starting at the reflex corner's neighbour
    const MeshData out = build_mesh("l.obj", m);
    ASSERT_EQ(out.indices.size(), 4u);
    float area = 0;
    int outline = 0;
    for (size_t t = 0; t < out.indices.size(); ++t) {
        const auto& i = out.indices[t];
        const Vec3 n = cross(out.positions[i[1]] - out.positions[i[0]],
                             out.positions[i[2]] - out.positions[i[1]]);
        EXPECT_GT(n.z, 0.0f);
        area += 0.5f * n.z;
        outline += std::popcount(unsigned(out.edge_flags[t]));
    }
    EXPECT_FLOAT_EQ(area, 3.0f);
    EXPECT_EQ(outline, 6);
}

std::string build_error(PolygonMesh m) {
    return input_error_of([&] { build_mesh("bad.ply", std::move(m)); });
}

TEST(MeshBuilder, BadFacesAreErrorsNamingFileLineAndFace) {
    PolygonMesh m = cube();
    m.corners[5] = 8;
    m.face_line = {3, 4, 5, 6, 7, 8};
    EXPECT_EQ(build_error(m), "bad.ply:4: face 2 refers to vertex 8, but the file has 8");
    PolygonMesh two;
    two.positions = {{0, 0, 0}, {1, 0, 0}};
    two.add_face({0, 1});
    EXPECT_EQ(build_error(two), "bad.ply: face 1 has 2 corners; a face needs 3 to 255");
    PolygonMesh flat;
    flat.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    flat.add_face({0, 1, 2});
    EXPECT_EQ(build_error(flat), "bad.ply: no usable triangles: all 1 are degenerate");
    PolygonMesh none;
    none.positions = {{0, 0, 0}};
    EXPECT_EQ(build_error(none), "bad.ply: no faces: the file defines no triangles or polygons");
}

TEST(MeshBuilder, SelfIntersectingFaceIsAWarning) {
    PolygonMesh m;
    m.positions = {{0, 0, 0}, {4, 4, 0}, {4, 0, 0}, {0, 1, 0}};
    m.add_face({0, 1, 2, 3});
    const MeshData out = build_mesh("bow.obj", m);
    ASSERT_EQ(out.warnings.size(), 1u);
    EXPECT_NE(out.warnings[0].find("face 1 crosses itself"), std::string::npos);
}

TEST(MeshBuilder, ObjSmoothingGroupsAndConcaveFacesThroughTheLoader) {
    testing::TempDir dir;
    std::ofstream(dir / "l.obj") << "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\n"
                                    "f 3 4 5 6 1 2\n";
    const MeshData l = load_obj(dir / "l.obj");
    EXPECT_EQ(l.indices.size(), 4u);
    std::ofstream(dir / "box.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                      "v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                      "s 1\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\n"
                                      "f 1 5 8 4\nf 2 3 7 6\n";
    EXPECT_EQ(load_obj(dir / "box.obj").positions.size(), 8u);  // one group: smooth
    std::ofstream(dir / "flat.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                       "v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                       "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\n"
                                       "f 1 5 8 4\nf 2 3 7 6\n";
    EXPECT_EQ(load_obj(dir / "flat.obj").positions.size(), 24u);  // no groups: crease angle
}

}  // namespace
TEST(MeshBuilder, VertexColoursFollowTheirVerticesThroughSplits) {
    PolygonMesh m = cube();
    for (const Vec3& p : m.positions) m.colors.push_back(p);  // colour = position
    const MeshData out = build_mesh("cube.ply", m);
    ASSERT_EQ(out.colors.size(), out.positions.size());
    EXPECT_EQ(out.positions.size(), 24u);
    for (size_t v = 0; v < out.positions.size(); ++v) EXPECT_EQ(out.colors[v], out.positions[v]);
    EXPECT_TRUE(build_mesh("cube.ply", cube()).colors.empty());
}

namespace {

/// A wavy grid of n × n quads (some concave, a bow tie in every few rows), a fan of 100
/// triangles round one vertex (a crowded point), a repeated triangle there and a degenerate
/// triangle: every path of build_mesh, over several of its chunks of faces.
PolygonMesh busy_mesh(int n) {
    PolygonMesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            m.positions.push_back(
                {float(i), float(j), 0.3f * std::sin(0.7f * float(i)) * std::cos(0.4f * float(j))});
    const auto at = [&](int i, int j) { return uint32_t(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            if ((i + j) % 7 == 0) {  // a concave pentagon: a corner pushed into the quad
                m.positions.push_back({float(i) + 0.5f, float(j) + 0.6f, 0.0f});
                const auto inner = uint32_t(m.positions.size() - 1);
                m.add_face({at(i, j), at(i + 1, j), at(i + 1, j + 1), inner, at(i, j + 1)});
            } else if (i == 3 && j % 5 == 0) {  // a bow tie
                m.add_face({at(i, j), at(i + 1, j + 1), at(i + 1, j), at(i, j + 1)});
            } else {
                m.add_face({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
            }
        }
    const auto centre = uint32_t(m.positions.size());
    m.positions.push_back({-5, -5, 1});
    for (int k = 0; k < 100; ++k) {
        const float a = 0.0628f * float(k), b = 0.0628f * float(k + 1);
        m.positions.push_back({-5 + std::cos(a), -5 + std::sin(a), 1 + 0.1f * float(k % 3)});
        m.positions.push_back({-5 + std::cos(b), -5 + std::sin(b), 1 + 0.1f * float(k % 2)});
        m.add_face({centre, uint32_t(m.positions.size() - 2), uint32_t(m.positions.size() - 1)});
    }
    m.add_face({centre, uint32_t(m.positions.size() - 2), uint32_t(m.positions.size() - 1)});
    m.add_face({0, 1, 0});  // a repeated corner: no area
    return m;
}

TEST(MeshBuilder, SameMeshOnOneThreadAsOnAll) {
    // triangulation, normals and welding run in parallel chunks: the result, its warnings and
    // its counts must not depend on the thread count
    const PolygonMesh mesh = busy_mesh(190);
    ASSERT_GT(mesh.face_count(), 2u * 16384u);
    MeshData one;
    {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = build_mesh("busy.obj", mesh);
    }
    const MeshData all = build_mesh("busy.obj", mesh);
    EXPECT_EQ(one.positions, all.positions);
    EXPECT_EQ(one.normals, all.normals);
    EXPECT_EQ(one.indices, all.indices);
    EXPECT_EQ(one.edge_flags, all.edge_flags);
    EXPECT_EQ(one.warnings, all.warnings);
    EXPECT_EQ(one.degenerate_skipped, all.degenerate_skipped);
    EXPECT_EQ(all.degenerate_skipped, 1u);
    ASSERT_FALSE(all.warnings.empty());  // the bow ties and the repeated triangle
}

TEST(MeshBuilder, TheFirstBadFaceInFileOrderIsReported) {
    // chunks of faces are checked in parallel; a later chunk failing first must not win
    PolygonMesh mesh = busy_mesh(190);
    mesh.corners[mesh.face_start[34000] + 1] = 999999999;  // in a late chunk
    mesh.corners[mesh.face_start[20000] + 2] = 888888888;  // in an earlier one
    const std::string e = input_error_of([&] { build_mesh("busy.obj", mesh); });
    EXPECT_NE(e.find("face 20001 refers to vertex 888888888"), std::string::npos) << e;
}

}  // namespace
}  // namespace hikari
