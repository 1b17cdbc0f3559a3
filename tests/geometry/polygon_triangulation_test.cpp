#include "hikari/geometry/polygon_triangulation.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <vector>

namespace hikari {
namespace {

/// Twice the signed area of the 2D polygon (x, y of each corner), positive counter-clockwise.
double doubled_area_xy(const std::vector<Vec3>& p) {
    double a = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        const Vec3 u = p[i], v = p[(i + 1) % p.size()];
        a += double(u.x) * v.y - double(v.x) * u.y;
    }
    return a;
}

/// Twice the area of each triangle, signed along `normal`.
std::vector<double> signed_areas(const std::vector<Vec3>& p,
                                 const std::vector<PolygonTriangle>& tris, Vec3 normal) {
    std::vector<double> out;
    for (const PolygonTriangle& t : tris) {
        const Vec3 a = p[t.corner[0]], b = p[t.corner[1]], c = p[t.corner[2]];
        out.push_back(dot(cross(b - a, c - b), normal));
    }
    return out;
}

bool inside_l_shape(double x, double y) {
    return x > 0 && y > 0 && x < 2 && y < 2 && !(x > 1 && y > 1);
}

// The lecture's Fig 4.9c case: a fan from the first corner of this L-shaped hexagon would cover
// its notch.
const std::vector<Vec3> k_l_shape = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0},
                                     {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};

TEST(PolygonTriangulation, TriangleIsItself) {
    std::vector<PolygonTriangle> out;
    const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    EXPECT_EQ(triangulate_polygon(p, out), PolygonShape::Convex);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].corner, (std::array<uint32_t, 3>{0, 1, 2}));
    EXPECT_EQ(out[0].edge_flags, 7);
}

TEST(PolygonTriangulation, ConvexQuadIsFannedFromItsFirstCorner) {
    std::vector<PolygonTriangle> out;
    const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    EXPECT_EQ(triangulate_polygon(p, out), PolygonShape::Convex);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(out[0].corner, (std::array<uint32_t, 3>{0, 1, 2}));
    EXPECT_EQ(out[1].corner, (std::array<uint32_t, 3>{0, 2, 3}));
    EXPECT_EQ(out[0].edge_flags, 0b011);  // 0→1, 1→2 on the outline; 2→0 is the diagonal
    EXPECT_EQ(out[1].edge_flags, 0b110);
}

TEST(PolygonTriangulation, ConcaveLShapeCoversExactlyItsOwnArea) {
    for (size_t start = 0; start < k_l_shape.size(); ++start) {
        // Every rotation of the corner list: whichever corner comes first, no fan is taken.
        std::vector<Vec3> p;
        for (size_t k = 0; k < k_l_shape.size(); ++k)
            p.push_back(k_l_shape[(start + k) % k_l_shape.size()]);
        std::vector<PolygonTriangle> out;
        EXPECT_EQ(triangulate_polygon(p, out), PolygonShape::Concave);
        ASSERT_EQ(out.size(), 4u);
        double total = 0;
        for (double a : signed_areas(p, out, {0, 0, 1})) {
            EXPECT_GT(a, 0.0);  // every triangle faces the polygon's way
            total += a;
        }
        EXPECT_NEAR(total, doubled_area_xy(p), 1e-9);
        for (const PolygonTriangle& t : out) {
            const Vec3 c = (p[t.corner[0]] + p[t.corner[1]] + p[t.corner[2]]) / 3.0f;
            EXPECT_TRUE(inside_l_shape(c.x, c.y)) << "triangle centre " << c.x << ", " << c.y;
        }
        int outline_edges = 0;
        for (const PolygonTriangle& t : out) outline_edges += std::popcount(unsigned(t.edge_flags));
        EXPECT_EQ(outline_edges, 6);  // each of the hexagon's edges exactly once
    }
}

TEST(PolygonTriangulation, ClockwiseTiltedPolygonKeepsItsOrientation) {
    // The L shape mirrored (clockwise seen from +z) and tilted: the triangles must face the way
    // the polygon does (its Newell normal), not +z.
    std::vector<Vec3> p;
    for (auto it = k_l_shape.rbegin(); it != k_l_shape.rend(); ++it)
        p.push_back({it->x, it->y * 0.6f, it->y * 0.8f + 3.0f});
    const Vec3 normal = normalize(Vec3{0, 0.8f, -0.6f});
    std::vector<PolygonTriangle> out;
    EXPECT_EQ(triangulate_polygon(p, out), PolygonShape::Concave);
    ASSERT_EQ(out.size(), 4u);
    double total = 0;
    for (double a : signed_areas(p, out, normal)) {
        EXPECT_GT(a, 0.0);
        total += a;
    }
    EXPECT_NEAR(total, 6.0, 1e-4);  // twice the L's area of 3
}

TEST(PolygonTriangulation, CombShapedPolygonIsClippedWithoutOverlap) {
    // A comb: many reflex corners, so most candidate ears hold another corner.
    std::vector<Vec3> p = {{0, 0, 0}, {9, 0, 0}, {9, 3, 0}};
    for (int x = 8; x >= 2; x -= 2) {
        p.push_back({float(x), 3, 0});
        p.push_back({float(x), 1, 0});
        p.push_back({float(x - 1), 1, 0});
        p.push_back({float(x - 1), 3, 0});
    }
    p.push_back({0, 3, 0});
    std::vector<PolygonTriangle> out;
    triangulate_polygon(p, out);
    ASSERT_EQ(out.size(), p.size() - 2);
    double total = 0;
    for (double a : signed_areas(p, out, {0, 0, 1})) {
        EXPECT_GE(a, 0.0);
        total += a;
    }
    EXPECT_NEAR(total, doubled_area_xy(p), 1e-6);
}

TEST(PolygonTriangulation, BowTieIsReportedAsSelfIntersecting) {
    std::vector<PolygonTriangle> out;
    const std::vector<Vec3> p = {{0, 0, 0}, {4, 4, 0}, {4, 0, 0}, {0, 1, 0}};
    EXPECT_EQ(triangulate_polygon(p, out), PolygonShape::SelfIntersecting);
    EXPECT_EQ(out.size(), 2u);
}

TEST(PolygonTriangulation, PentagramIsNotTakenForConvex) {
    // Every corner of a pentagram turns left, but it winds twice round its centre.
    std::vector<Vec3> p;
    for (int k = 0; k < 5; ++k) {
        const double a = 2.0 * M_PI * (2 * k) / 5.0;
        p.push_back({float(std::cos(a)), float(std::sin(a)), 0});
    }
    std::vector<PolygonTriangle> out;
    EXPECT_EQ(triangulate_polygon(p, out), PolygonShape::SelfIntersecting);
    EXPECT_EQ(out.size(), 3u);
}

TEST(PolygonTriangulation, CollinearCornersAreDegenerate) {
    std::vector<PolygonTriangle> out;
    const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
    EXPECT_EQ(triangulate_polygon(p, out), PolygonShape::Degenerate);
    EXPECT_EQ(out.size(), 2u);
}

}  // namespace
}  // namespace hikari
