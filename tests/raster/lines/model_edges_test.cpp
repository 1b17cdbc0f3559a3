#include "hikari/raster/lines/model_edges.h"

#include <gtest/gtest.h>

#include <set>

#include "../../io/temp_dir.h"
#include "hikari/io/models/obj_loader.h"
#include "line_test_util.h"

namespace hikari {
namespace {

TriangleSet triangles_of(const MeshData& mesh) {
    TriangleSet t;
    t.positions = mesh.positions;
    t.normals = mesh.normals;
    t.indices = mesh.indices;
    t.edge_flags = mesh.edge_flags;
    t.material.assign(mesh.indices.size(), 0);
    for (uint32_t k = 0; k < mesh.indices.size(); ++k) t.id.push_back(k);
    return t;
}

TEST(ModelEdges, BoxOfQuadsHasTwelveEdgesAndSixDiagonals) {
    testing::TempDir dir;
    testing::write_text(dir / "box.obj", testing::box_obj({0, 0, 0}, {1, 2, 3}));
    // Split every vertex, as normals per face would: edges still pair by position.
    MeshData mesh = load_obj(dir / "box.obj");
    TriangleSet t = triangles_of(mesh);
    TriangleSet split = t;
    split.positions.clear();
    split.indices.clear();
    for (const auto& tri : t.indices) {
        const auto base = static_cast<uint32_t>(split.positions.size());
        for (const uint32_t v : tri) split.positions.push_back(t.positions[v]);
        split.indices.push_back({base, base + 1, base + 2});
    }
    const std::vector<ModelEdge> edges = model_edges(split);
    ASSERT_EQ(edges.size(), 18u);
    size_t own = 0;
    for (const ModelEdge& e : edges) {
        own += e.own;
        // Closed surface: every edge has two faces.
        EXPECT_NE(e.faces[0], k_no_face);
        EXPECT_NE(e.faces[1], k_no_face);
        EXPECT_NE(e.faces[0], e.faces[1]);
        const Vec3 d = split.positions[e.v1] - split.positions[e.v0];
        // A model edge runs along one axis; a diagonal does not.
        const int zero = (d.x == 0) + (d.y == 0) + (d.z == 0);
        EXPECT_EQ(e.own, zero == 2);
    }
    EXPECT_EQ(own, 12u);
}

TEST(ModelEdges, SilhouetteIsBetweenFacesTurnedDifferently) {
    ModelEdge e;
    e.faces = {0, 1};
    EXPECT_TRUE(is_silhouette(e, {0, 1}));
    EXPECT_FALSE(is_silhouette(e, {1, 1}));
    e.faces[1] = k_no_face;
    EXPECT_FALSE(is_silhouette(e, {0, 1}));
}

}  // namespace
}  // namespace hikari
