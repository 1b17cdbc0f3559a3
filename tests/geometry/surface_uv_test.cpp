#include "hikari/geometry/surface_uv.h"

#include <cmath>

#include <gtest/gtest.h>

#include "../support/expect_near.h"

namespace hikari {
namespace {

using testing::expect_near;

const Sphere k_sphere{{1, 2, 3}, 2.0f};

/// The point of k_sphere in unit direction d.
Vec3 on_sphere(Vec3 d) { return k_sphere.center + k_sphere.radius * normalize(d); }

TEST(SphereUv, LongitudeAndLatitudeConventions) {
    // Facing +z (a camera looking down −z sees it): the middle of the image.
    EXPECT_NEAR(sphere_uv(k_sphere, on_sphere({0, 0, 1})).uv.x, 0.5f, 1e-6f);
    EXPECT_NEAR(sphere_uv(k_sphere, on_sphere({0, 0, 1})).uv.y, 0.5f, 1e-6f);
    // u grows to the right seen from +z (toward +x), the seam faces −z.
    EXPECT_NEAR(sphere_uv(k_sphere, on_sphere({1, 0, 0})).uv.x, 0.75f, 1e-6f);
    EXPECT_NEAR(sphere_uv(k_sphere, on_sphere({-1, 0, 0})).uv.x, 0.25f, 1e-6f);
    EXPECT_NEAR(sphere_uv(k_sphere, on_sphere({-1e-4f, 0, -1})).uv.x, 0.0f, 1e-4f);
    EXPECT_NEAR(sphere_uv(k_sphere, on_sphere({1e-4f, 0, -1})).uv.x, 1.0f, 1e-4f);
    // v: 0 at the south pole, 1 at the north pole, 3/4 at latitude 45°.
    EXPECT_NEAR(sphere_uv(k_sphere, on_sphere({0, 1, 0})).uv.y, 1.0f, 1e-6f);
    EXPECT_NEAR(sphere_uv(k_sphere, on_sphere({0, -1, 0})).uv.y, 0.0f, 1e-6f);
    EXPECT_NEAR(sphere_uv(k_sphere, on_sphere({0, 1, 1})).uv.y, 0.75f, 1e-5f);
}

TEST(SphereUv, GradientsMatchFiniteDifferences) {
    for (const Vec3 d :
         {Vec3(0.3f, 0.4f, 0.8f), Vec3(-0.7f, -0.5f, 0.2f), Vec3(0.1f, 0.9f, -0.3f)}) {
        const Vec3 p = on_sphere(d);
        const SurfaceUv at = sphere_uv(k_sphere, p);
        // Small steps along the surface, in two tangent directions.
        const Vec3 n = normalize(d);
        const Vec3 t1 = normalize(cross(n, Vec3(0, 1, 0))), t2 = cross(n, t1);
        for (const Vec3 t : {t1, t2}) {
            const float h = 1e-3f;
            const SurfaceUv a = sphere_uv(k_sphere, on_sphere(p + h * t - k_sphere.center));
            const SurfaceUv b = sphere_uv(k_sphere, on_sphere(p - h * t - k_sphere.center));
            EXPECT_NEAR(dot(at.du_dp, t), (a.uv.x - b.uv.x) / (2 * h), 2e-3f);
            EXPECT_NEAR(dot(at.dv_dp, t), (a.uv.y - b.uv.y) / (2 * h), 2e-3f);
        }
    }
}

TEST(PlaneUv, AxesOfFloorsAndWalls) {
    Plane floor{{0, 0, 0}, {0, 1, 0}};
    auto axes = plane_uv_axes(floor);
    expect_near(axes[0], {1, 0, 0}, 1e-6f);
    expect_near(axes[1], {0, 0, -1}, 1e-6f);
    axes = plane_uv_axes(Plane{{0, 0, 0}, {0, 0, 1}});
    expect_near(axes[0], {1, 0, 0}, 1e-6f);
    expect_near(axes[1], {0, 1, 0}, 1e-6f);
    axes = plane_uv_axes(Plane{{0, 0, 0}, {1, 0, 0}});
    expect_near(axes[0], {0, 0, -1}, 1e-6f);
    expect_near(axes[1], {0, 1, 0}, 1e-6f);
    // A tilted plane: the axes are unit, in the plane and right-handed with the normal.
    const Plane tilted{{0, 0, 0}, normalize(Vec3(0.3f, 0.8f, -0.5f))};
    axes = plane_uv_axes(tilted);
    EXPECT_NEAR(length(axes[0]), 1.0f, 1e-6f);
    EXPECT_NEAR(dot(axes[0], tilted.normal), 0.0f, 1e-6f);
    expect_near(cross(axes[0], axes[1]), tilted.normal, 1e-6f);
}

TEST(PlaneUv, ScaleAndOrigin) {
    Plane floor{{2, -1, 5}, {0, 1, 0}};
    floor.uv_scale = 4.0f;
    const SurfaceUv at = plane_uv(floor, {2 + 6, -1, 5 - 2});
    EXPECT_NEAR(at.uv.x, 1.5f, 1e-6f);
    EXPECT_NEAR(at.uv.y, 0.5f, 1e-6f);
    expect_near(at.du_dp, {0.25f, 0, 0}, 1e-7f);
    expect_near(at.dv_dp, {0, 0, -0.25f}, 1e-7f);
}

TEST(TriangleUv, GradientsReproduceTheCornerDifferences) {
    const std::array<Vec3, 3> p{Vec3(0, 0, 0), Vec3(3, 1, 0), Vec3(-1, 2, 2)};
    const std::array<Vec2, 3> t{Vec2{0.1f, 0.2f}, Vec2{0.9f, 0.3f}, Vec2{0.4f, 1.1f}};
    const SurfaceUv g = triangle_uv_gradients(p, t);
    for (int k = 1; k < 3; ++k) {
        EXPECT_NEAR(dot(g.du_dp, p[k] - p[0]), t[k].x - t[0].x, 1e-6f);
        EXPECT_NEAR(dot(g.dv_dp, p[k] - p[0]), t[k].y - t[0].y, 1e-6f);
    }
    // In the triangle's plane: nothing changes along its normal.
    const Vec3 n = cross(p[1] - p[0], p[2] - p[0]);
    EXPECT_NEAR(dot(g.du_dp, n), 0.0f, 1e-5f);
    // A degenerate triangle has no gradient.
    const SurfaceUv none = triangle_uv_gradients({p[0], p[1], p[1]}, t);
    expect_near(none.du_dp, Vec3(0.0f), 0.0f);
}

}  // namespace
}  // namespace hikari
