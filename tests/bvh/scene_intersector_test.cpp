// The scene intersector's nearest hits and shadow rays against testing every primitive in the
// order it always has: triangles, then spheres in index order, then planes, each later one
// strictly nearer; and the spheres held in their BVH, not tested one by one.
#include "hikari/bvh/scene_intersector.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>

#include "hikari/bvh/wide_bvh_traversal.h"
#include "hikari/geometry/intersect.h"
#include "test_meshes.h"

namespace hikari {
namespace {

/// Triangles, many spheres (a twin for exact ties, some not casting shadows) and two planes.
Scene mixed_scene(uint64_t seed) {
    Pcg32 rng(seed, 9);
    Scene scene;
    scene.materials.resize(2);
    PrimitiveId id = 0;
    testing::set_scene_triangles(scene.triangles, testing::random_soup(500, 0.3f, seed), id,
                                 [](size_t) { return uint32_t{1}; });
    for (size_t i = 0; i < scene.triangles.size(); ++i)
        scene.triangles.casts_shadow.push_back(i % 5 == 0 ? 0 : 1);
    for (int i = 0; i < 1500; ++i) {
        Sphere s;
        s.center = testing::random_point(rng, 1.0f);
        s.radius = 0.01f + 0.08f * rng.next_float();
        s.id = id++;
        s.casts_shadow = i % 4 != 1;
        scene.spheres.push_back(s);
    }
    Sphere twin = scene.spheres[7];
    twin.id = id++;
    scene.spheres.push_back(twin);
    for (int i = 0; i < 2; ++i) {
        Plane p;
        p.point = testing::random_point(rng, 1.2f);
        p.normal = testing::random_direction(rng);
        p.id = id++;
        p.casts_shadow = i == 0;
        scene.planes.push_back(p);
    }
    scene.primitive_count = id;
    return scene;
}

struct Reference {
    HitKind kind = HitKind::none;
    uint32_t index = 0;
    float t = k_infinity;
};

/// What SceneIntersector::closest answered before spheres had a BVH: spheres and planes one by
/// one after the triangles (found here through the triangle BVH, itself checked against brute
/// force in wide_bvh_traversal_test.cpp).
Reference reference_closest(const Scene& scene, const SceneIntersector& intersector, const Ray& ray,
                            Interval range) {
    Reference r;
    if (TriangleHit h; intersect_closest(intersector.bvh(), ray, range, h))
        r = {HitKind::triangle, h.triangle, h.t}, range.max = h.t;
    for (uint32_t i = 0; i < scene.spheres.size(); ++i) {
        const float t =
            intersect_sphere(ray, scene.spheres[i].center, scene.spheres[i].radius, range);
        if (t == t) r = {HitKind::sphere, i, t}, range.max = t;
    }
    for (uint32_t i = 0; i < scene.planes.size(); ++i) {
        const float t = intersect_plane(ray, scene.planes[i].point, scene.planes[i].normal, range);
        if (t == t) r = {HitKind::plane, i, t}, range.max = t;
    }
    return r;
}

bool reference_occluded(const Scene& scene, const SceneIntersector& intersector, const Ray& ray,
                        Interval range) {
    if (intersector.occluded_by_triangles(ray, range)) return true;
    for (const Sphere& s : scene.spheres)
        if (s.casts_shadow && !std::isnan(intersect_sphere(ray, s.center, s.radius, range)))
            return true;
    for (const Plane& p : scene.planes)
        if (p.casts_shadow && !std::isnan(intersect_plane(ray, p.point, p.normal, range)))
            return true;
    return false;
}

TEST(SceneIntersector, MixedScenesMatchOneByOne) {
    for (uint64_t seed = 1; seed <= 3; ++seed) {
        SCOPED_TRACE(seed);
        const Scene scene = mixed_scene(seed);
        const SceneIntersector intersector(scene);
        Pcg32 rng(seed, 4);
        int spheres_hit = 0, shadowed = 0;
        for (int r = 0; r < 3000; ++r) {
            SCOPED_TRACE(r);
            const Ray ray{testing::random_point(rng, 1.5f), testing::random_direction(rng)};
            const Interval range{0.0f, r % 2 == 0 ? k_infinity : 0.5f};
            const Reference expected = reference_closest(scene, intersector, ray, range);
            SurfaceHit hit;
            ASSERT_EQ(intersector.closest(ray, range, hit), expected.kind != HitKind::none);
            ASSERT_EQ(intersector.occluded(ray, range),
                      reference_occluded(scene, intersector, ray, range));
            shadowed += intersector.occluded(ray, range);
            if (expected.kind == HitKind::none) continue;
            EXPECT_EQ(hit.kind, expected.kind);
            EXPECT_EQ(hit.index, expected.index);
            EXPECT_EQ(std::bit_cast<uint32_t>(hit.t), std::bit_cast<uint32_t>(expected.t));
            if (hit.kind != HitKind::sphere) continue;
            ++spheres_hit;
            const Sphere& s = scene.spheres[hit.index];
            EXPECT_EQ(hit.id, s.id);
            EXPECT_EQ(hit.position, ray.at(hit.t));
            EXPECT_EQ(hit.geometric_normal, (hit.position - s.center) / s.radius);
        }
        EXPECT_GT(spheres_hit, 500);
        EXPECT_GT(shadowed, 500);
    }
}

TEST(SceneIntersector, ShadowRaysPassSpheresThatCastNoShadow) {
    Scene scene;
    scene.materials.resize(1);
    Sphere ghost;
    ghost.center = {0, 0, -3};
    ghost.casts_shadow = false;
    scene.spheres.push_back(ghost);
    const SceneIntersector ghost_only(scene);
    const Ray ray{{0, 0, 0}, {0, 0, -1}};
    SurfaceHit hit;
    EXPECT_TRUE(ghost_only.closest(ray, {0.0f, k_infinity}, hit));  // seen, but no shadow
    EXPECT_FALSE(ghost_only.occluded(ray, {0.0f, k_infinity}));
    Sphere blocker = ghost;
    blocker.center = {0, 0, -6};
    blocker.casts_shadow = true;
    scene.spheres.push_back(blocker);
    const SceneIntersector both(scene);
    EXPECT_FALSE(both.occluded(ray, {0.0f, 4.5f}));  // only the ghost lies before 4.5
    EXPECT_TRUE(both.occluded(ray, {0.0f, k_infinity}));
}

TEST(SceneIntersector, HoldsEverySphereInItsBvh) {
    // Not timing: the structure. A million spheres traced one by one would never finish; held in
    // the wide BVH, each leaf has at most 16 of them and a ray visits few leaves.
    const Scene scene = mixed_scene(4);
    const SceneIntersector intersector(scene);
    const SphereBvh& spheres = intersector.sphere_bvh();
    EXPECT_EQ(spheres.sphere_count(), scene.spheres.size());
    EXPECT_GE(spheres.tree.nodes.size(), scene.spheres.size() / (8 * WideBvhRef::k_max_leaf_size));
    EXPECT_FALSE(WideBvhRef::is_leaf(spheres.tree.root));
    RenderStats stats;
    report_bvh_stats(intersector, &stats);
    EXPECT_EQ(stats.bvh_spheres.load(), scene.spheres.size());
    EXPECT_EQ(stats.bvh_sphere_nodes.load(), spheres.tree.nodes.size());
}

}  // namespace
}  // namespace hikari
