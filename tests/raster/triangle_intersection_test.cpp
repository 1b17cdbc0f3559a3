#include "hikari/raster/triangle_intersection.h"

#include <gtest/gtest.h>

namespace hikari {
namespace {

TEST(TriangleIntersection, PiercingTrianglesMeetAlongTheirCommonSegment) {
    // A in the plane z = 0; B in the plane x = 0.2, crossing z = 0 for y in [−1, 1].
    const Vec3 a[3] = {{-1, -2, 0}, {1, -2, 0}, {0, 2, 0}};
    const Vec3 b[3] = {{0.2f, -1, -1}, {0.2f, 1, -1}, {0.2f, 0, 1}};
    Vec3 p, q;
    ASSERT_TRUE(triangle_intersection(a, b, p, q));
    if (p.y > q.y) std::swap(p, q);
    // B meets z = 0 along y ∈ [−0.5, 0.5] (its edges from y = ±1 at z = −1 to y = 0 at z = 1);
    // A covers x = 0.2 for y ∈ [−2, 1.6]: the overlap is B's part.
    EXPECT_NEAR(p.x, 0.2f, 1e-6f);
    EXPECT_NEAR(q.x, 0.2f, 1e-6f);
    EXPECT_NEAR(p.z, 0.0f, 1e-6f);
    EXPECT_NEAR(p.y, -0.5f, 1e-6f);
    EXPECT_NEAR(q.y, 0.5f, 1e-6f);
}

TEST(TriangleIntersection, SeparateTouchingOrCoplanarTrianglesDoNot) {
    const Vec3 a[3] = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    const Vec3 above[3] = {{-1, -1, 1}, {1, -1, 1}, {0, 1, 2}};
    const Vec3 coplanar[3] = {{-1, -1, 0}, {2, -1, 0}, {0, 3, 0}};
    const Vec3 beside[3] = {{5, -1, -1}, {5, 1, -1}, {5, 0, 1}};  // its plane cuts A's, apart
    Vec3 p, q;
    EXPECT_FALSE(triangle_intersection(a, above, p, q));
    EXPECT_FALSE(triangle_intersection(a, coplanar, p, q));
    EXPECT_FALSE(triangle_intersection(a, beside, p, q));
}

}  // namespace
}  // namespace hikari
