// build_mesh() at points shared by very many faces (issue 26): copies of one triangle, a fan of
// hundreds of thousands of triangles around one vertex. The normals must be what smoothing face
// by face gives, whatever the number of faces at the point (the cost is not asserted here).

#include <gtest/gtest.h>

#include <cmath>

#include "hikari/io/models/mesh_builder.h"

namespace hikari {
namespace {

constexpr uint32_t k_many = 200000;

/// The corner angle of a triangle at p, between the edges to q and r.
float angle_at(Vec3 p, Vec3 q, Vec3 r) {
    return std::acos(dot(normalize(q - p), normalize(r - p)));
}

/// `count` triangles around vertex 0 at the origin, spanning the disc of radius 1 in the plane
/// z = 0, counter-clockwise seen from +z.
PolygonMesh flat_fan(uint32_t count) {
    PolygonMesh m;
    m.positions.push_back({0, 0, 0});
    for (uint32_t k = 0; k < count; ++k) {
        const float a = 2.0f * float(M_PI) * float(k) / float(count);
        m.positions.push_back({std::cos(a), std::sin(a), 0});
    }
    for (uint32_t k = 0; k < count; ++k) m.add_face({0, 1 + k, 1 + (k + 1) % count});
    return m;
}

TEST(MeshBuilderValence, FlatFanOfManyTrianglesHasTheFaceNormalEverywhere) {
    const MeshData m = build_mesh("fan.obj", flat_fan(k_many));
    ASSERT_EQ(m.indices.size(), size_t{k_many});
    EXPECT_EQ(m.positions.size(), size_t{k_many} + 1);  // nothing split: one plane
    for (const Vec3& n : m.normals) {
        EXPECT_NEAR(n.x, 0.0f, 1e-6f);
        EXPECT_NEAR(n.y, 0.0f, 1e-6f);
        EXPECT_NEAR(n.z, 1.0f, 1e-6f);
    }
}

TEST(MeshBuilderValence, ConeApexOfManyTrianglesIsSmoothedAlongTheAxis) {
    // The apex of a cone of many segments, raised so its faces lean 45 degrees: with a crease
    // angle of 180 every face at the apex counts, and they balance out to the axis.
    PolygonMesh m = flat_fan(k_many);
    m.positions[0] = {0, 0, 1};
    const MeshData out = build_mesh("cone.obj", std::move(m), {.crease_angle_degrees = 180});
    ASSERT_EQ(out.indices.size(), size_t{k_many});
    const Vec3 apex = out.normals[out.indices[0][0]];
    EXPECT_NEAR(apex.z, 1.0f, 1e-4f);
    // A ring vertex is shared by two neighbouring faces: its normal leans out, 45 degrees up.
    const Vec3 rim = out.normals[out.indices[0][1]];
    EXPECT_NEAR(rim.z, std::sqrt(0.5f), 1e-3f);
}

TEST(MeshBuilderValence, CopiesOfOneTriangleEachCountAsBefore) {
    // Many exact copies of triangle A and one triangle B at 30 degrees to it, all sharing vertex
    // 0: each copy adds its weight, as when the corners are smoothed one by one. Each copy has a
    // material of its own, so none is a repeat that build_mesh drops.
    PolygonMesh m;
    const float c = std::cos(float(M_PI) / 6), s = std::sin(float(M_PI) / 6);
    // A in the plane z = 0; B beside it, folded 30 degrees down about the y axis.
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {c, 0, -s}};
    constexpr uint32_t copies = 1000;
    m.materials.resize(copies);
    for (uint32_t k = 0; k < copies; ++k) {
        m.add_face({0, 1, 2});
        m.face_material.push_back(int32_t(k));
    }
    m.add_face({0, 3, 4});
    m.face_material.push_back(0);
    const Vec3 a_normal = normalize(cross(m.positions[1], m.positions[2] - m.positions[1]));
    const Vec3 b_normal =
        normalize(cross(m.positions[3] - m.positions[0], m.positions[4] - m.positions[3]));
    const float a_angle = angle_at(m.positions[0], m.positions[1], m.positions[2]);
    const float b_angle = angle_at(m.positions[0], m.positions[3], m.positions[4]);
    const Vec3 expected = normalize(float(copies) * a_angle * a_normal + b_angle * b_normal);

    const MeshData out = build_mesh("copies.obj", std::move(m));
    ASSERT_EQ(out.indices.size(), size_t{copies} + 1);
    for (size_t t = 0; t < out.indices.size(); ++t) {
        const Vec3 n = out.normals[out.indices[t][0]];
        EXPECT_NEAR(dot(n, expected), 1.0f, 1e-6f) << "triangle " << t;
        EXPECT_EQ(out.indices[t][0], out.indices[0][0]);  // one smoothed vertex for all
    }
    // The corners not shared with B keep A's face normal, and the copies share them.
    EXPECT_NEAR(dot(out.normals[out.indices[0][1]], a_normal), 1.0f, 1e-6f);
    EXPECT_EQ(out.indices[copies - 1][1], out.indices[0][1]);
}

TEST(MeshBuilderValence, ExactRepeatsAreDroppedBeforeSmoothing) {
    // The same copies with one material: all but the first are repeats (mesh_builder.cpp), so
    // the smoothed normal at vertex 0 weighs A once.
    PolygonMesh m;
    const float c = std::cos(float(M_PI) / 6), s = std::sin(float(M_PI) / 6);
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {c, 0, -s}};
    for (uint32_t k = 0; k < 1000; ++k) m.add_face({0, 1, 2});
    m.add_face({0, 3, 4});
    const Vec3 a_normal = normalize(cross(m.positions[1], m.positions[2] - m.positions[1]));
    const Vec3 b_normal =
        normalize(cross(m.positions[3] - m.positions[0], m.positions[4] - m.positions[3]));
    const float a_angle = angle_at(m.positions[0], m.positions[1], m.positions[2]);
    const float b_angle = angle_at(m.positions[0], m.positions[3], m.positions[4]);
    const Vec3 expected = normalize(a_angle * a_normal + b_angle * b_normal);
    const MeshData out = build_mesh("copies.obj", std::move(m));
    ASSERT_EQ(out.indices.size(), 2u);
    EXPECT_NEAR(dot(out.normals[out.indices[0][0]], expected), 1.0f, 1e-6f);
}

TEST(MeshBuilderValence, ManyCopiesAcrossACreaseStaySplit) {
    // Copies of two faces meeting at 90 degrees along an edge: the crease (45) keeps each side
    // flat, however many copies share the edge's points. Each pair has a material of its own, so
    // no copy is a repeat that build_mesh drops.
    PolygonMesh m;
    m.positions = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}};
    m.materials.resize(k_many / 2);
    for (uint32_t k = 0; k < k_many / 2; ++k) {
        m.add_face({0, 2, 1});  // in z = 0, facing +z
        m.add_face({0, 1, 3});  // in x = 0, facing +x
        m.face_material.insert(m.face_material.end(), {int32_t(k), int32_t(k)});
    }
    const MeshData out = build_mesh("pile.obj", std::move(m));
    ASSERT_EQ(out.indices.size(), size_t{k_many});
    EXPECT_EQ(out.positions.size(), 6u);  // the edge's two points, once per side
    for (size_t t = 0; t < out.indices.size(); ++t)
        for (uint32_t v : out.indices[t]) {
            const Vec3 expected = t % 2 == 0 ? Vec3(0, 0, 1) : Vec3(1, 0, 0);
            EXPECT_NEAR(dot(out.normals[v], expected), 1.0f, 1e-6f);
        }
}

}  // namespace
}  // namespace hikari
