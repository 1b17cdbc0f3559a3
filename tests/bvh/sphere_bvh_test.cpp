// The spheres' wide BVH (bvh/sphere_bvh.h) against testing every sphere in index order: the same
// nearest sphere, bit for bit the same t, at every SIMD level, and the same any-hit answer.
#include "hikari/bvh/sphere_bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "hikari/bvh/wide_bvh_builder.h"
#include "hikari/bvh/wide_bvh_traversal.h"
#include "hikari/core/error.h"
#include "hikari/core/memory_budget.h"
#include "hikari/geometry/intersect.h"
#include "test_meshes.h"

namespace hikari {
namespace {

/// `count` spheres with centres in [-1, 1]^3 and radii in [0.005, 0.005 + max_radius), some
/// overlapping, every tenth a twin of the one before it (same t: the first must win), every
/// seventh not casting shadows.
std::vector<Sphere> random_spheres(uint32_t count, float max_radius, uint64_t seed) {
    Pcg32 rng(seed, 3);
    std::vector<Sphere> spheres;
    for (uint32_t i = 0; i < count; ++i) {
        Sphere s;
        s.center = testing::random_point(rng, 1.0f);
        s.radius = 0.005f + max_radius * rng.next_float();
        if (i % 10 == 9) s = spheres.back();
        s.id = i;
        s.casts_shadow = i % 7 != 3;
        spheres.push_back(s);
    }
    return spheres;
}

/// The reference: every sphere in index order, each later one strictly nearer.
std::optional<SphereHit> brute_force_closest(const std::vector<Sphere>& spheres, const Ray& ray,
                                             Interval valid) {
    std::optional<SphereHit> best;
    for (uint32_t i = 0; i < spheres.size(); ++i) {
        const float t = intersect_sphere(ray, spheres[i].center, spheres[i].radius, valid);
        if (t == t) best = SphereHit{t, i}, valid.max = t;
    }
    return best;
}

bool brute_force_any(const std::vector<Sphere>& spheres, const Ray& ray, Interval valid,
                     bool casters_only) {
    for (const Sphere& s : spheres)
        if ((s.casts_shadow || !casters_only) &&
            !std::isnan(intersect_sphere(ray, s.center, s.radius, valid)))
            return true;
    return false;
}

/// Rays from inside and around the cloud, in random directions, over random ranges.
void expect_matches_brute_force(const std::vector<Sphere>& spheres, uint64_t seed) {
    const SphereBvh bvh = build_sphere_bvh(spheres);
    const SphereBvh casters = build_sphere_bvh(spheres, true);
    ASSERT_EQ(bvh.sphere_count(), spheres.size());
    Pcg32 rng(seed, 5);
    int hits = 0;
    for (int r = 0; r < 3000; ++r) {
        SCOPED_TRACE(r);
        const Ray ray{testing::random_point(rng, 1.5f), testing::random_direction(rng)};
        const Interval valid{r % 3 == 0 ? 0.01f : 0.0f, r % 4 == 0 ? 1.0f : k_infinity};
        const auto expected = brute_force_closest(spheres, ray, valid);
        hits += expected.has_value();
        for (SimdLevel level : supported_simd_levels()) {
            SCOPED_TRACE(simd_level_name(level));
            SphereHit hit;
            const bool found = intersect_closest(bvh, ray, valid, hit, level);
            ASSERT_EQ(found, expected.has_value());
            EXPECT_EQ(intersect_any(bvh, ray, valid, level), found);
            EXPECT_EQ(intersect_any(casters, ray, valid, level),
                      brute_force_any(spheres, ray, valid, true));
            if (!found) continue;
            EXPECT_EQ(std::bit_cast<uint32_t>(hit.t), std::bit_cast<uint32_t>(expected->t));
            EXPECT_EQ(hit.sphere, expected->sphere);
        }
    }
    EXPECT_GT(hits, 300);
}

TEST(SphereBvh, ManySmallSpheresMatchBruteForce) {
    expect_matches_brute_force(random_spheres(5000, 0.03f, 1), 11);
}

TEST(SphereBvh, OverlappingLargeSpheresMatchBruteForce) {
    // Rays start inside several spheres at once; nearest hits are often far sides.
    expect_matches_brute_force(random_spheres(300, 0.5f, 2), 12);
}

TEST(SphereBvh, HoldsEverySphereOnceAndCastersOnlyWhenAsked) {
    const std::vector<Sphere> spheres = random_spheres(2000, 0.05f, 3);
    const SphereBvh all = build_sphere_bvh(spheres);
    const SphereBvh casters = build_sphere_bvh(spheres, true);
    std::vector<int> seen(spheres.size(), 0);
    for (uint32_t slot = 0; slot < all.sphere_count(); ++slot) {
        const uint32_t i = all.tree.triangle_ids[slot];
        ++seen[i];
    }
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
    EXPECT_FALSE(all.tree.nodes.empty());
    size_t expected_casters = 0;
    for (const Sphere& s : spheres) expected_casters += s.casts_shadow;
    EXPECT_EQ(casters.sphere_count(), expected_casters);
    for (uint32_t slot = 0; slot < casters.sphere_count(); ++slot)
        EXPECT_TRUE(spheres[casters.tree.triangle_ids[slot]].casts_shadow);
}

TEST(SphereBvh, NonFiniteSpheresAreLeftOut) {
    std::vector<Sphere> spheres = random_spheres(20, 0.1f, 4);
    spheres[3].center.x = NAN;
    spheres[5].radius = INFINITY;
    EXPECT_EQ(build_sphere_bvh(spheres).sphere_count(), 18u);
    EXPECT_TRUE(build_sphere_bvh({}).empty());
}

TEST(SphereBvh, BuildsRefuseBeyondTheMemoryLimit) {
    // Both builds ask the memory budget before they allocate, and say what they were building.
    const double saved = memory_limit();
    set_memory_limit(64 * 1024);
    const std::vector<Sphere> spheres = random_spheres(5000, 0.01f, 5);
    const testing::TestMesh mesh = testing::random_soup(5000, 0.1f, 5);
    std::string sphere_message, triangle_message;
    try {
        build_sphere_bvh(spheres);
    } catch (const InputError& e) {
        sphere_message = e.what();
    }
    try {
        build_wide_bvh(mesh.positions, mesh.indices);
    } catch (const InputError& e) {
        triangle_message = e.what();
    }
    set_memory_limit(saved);
    EXPECT_NE(sphere_message.find("5000 spheres"), std::string::npos) << sphere_message;
    EXPECT_NE(triangle_message.find("the BVH of 5000 triangles"), std::string::npos)
        << triangle_message;
    EXPECT_EQ(build_sphere_bvh(spheres).sphere_count(), spheres.size());  // limit restored
}

}  // namespace
}  // namespace hikari
