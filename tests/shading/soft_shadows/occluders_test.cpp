// The analytic soft shadow's casters (shading/soft_shadows/occluders.h): spheres are found
// through their own BVH, and the answers are those of asking every sphere.

#include "hikari/shading/soft_shadows/occluders.h"

#include <cmath>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>

namespace hikari {
namespace {

std::vector<Sphere> random_spheres(size_t count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> at(-5.0f, 5.0f), size(0.02f, 0.2f);
    std::vector<Sphere> spheres(count);
    for (size_t i = 0; i < count; ++i) {
        spheres[i].center = {at(rng), at(rng), at(rng)};
        spheres[i].radius = size(rng);
        spheres[i].casts_shadow = i % 7 != 0;  // some do not cast
        spheres[i].id = static_cast<uint32_t>(i);
    }
    return spheres;
}

/// Whether the sphere reaches into every half-space (n, d): dot(n, x) >= d.
bool meets_region(const Sphere& s, const std::vector<Vec4>& planes) {
    for (const Vec4& p : planes)
        if (dot(p.xyz(), s.center) - p.w < -s.radius * length(p.xyz())) return false;
    return true;
}

TEST(Occluders, SpheresInARegionAreFoundWithoutVisitingEveryOne) {
    const std::vector<Sphere> spheres = random_spheres(3000, 1);
    const OccluderSet occluders({}, {}, {}, spheres, {});
    // A box of side 2 around a point: the planes x >= x0 - 1, -x >= -(x0 + 1), ...
    std::mt19937 rng(2);
    std::uniform_real_distribution<float> at(-4.0f, 4.0f);
    for (int trial = 0; trial < 20; ++trial) {
        const Vec3 c{at(rng), at(rng), at(rng)};
        std::vector<Vec4> planes;
        for (int a = 0; a < 3; ++a) {
            Vec3 n(0.0f);
            n[a] = 1.0f;
            planes.emplace_back(n.x, n.y, n.z, c[a] - 1.0f);
            planes.emplace_back(-n.x, -n.y, -n.z, -(c[a] + 1.0f));
        }
        std::multiset<uint32_t> visited;
        occluders.for_each_sphere_in(planes, [&](const Sphere& s) { visited.insert(s.id); });
        size_t inside = 0;
        for (const Sphere& s : spheres) {
            if (!s.casts_shadow || !meets_region(s, planes)) continue;
            ++inside;
            EXPECT_EQ(visited.count(s.id), 1u) << "sphere " << s.id << ", trial " << trial;
        }
        for (uint32_t id : visited) EXPECT_TRUE(spheres[id].casts_shadow) << id;
        EXPECT_GE(visited.size(), inside);
        EXPECT_LT(visited.size(), spheres.size() / 4) << "the tree ruled out no sphere";
    }
}

TEST(Occluders, SphereBlockingMatchesAskingEverySphere) {
    const std::vector<Sphere> spheres = random_spheres(2000, 3);
    const OccluderSet occluders({}, {}, {}, spheres, {});
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> at(-6.0f, 6.0f);
    int blocked = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const Vec3 from{at(rng), at(rng), at(rng)}, to{at(rng), at(rng), at(rng)};
        const float t_max = length(to - from);
        const Vec3 dir = (to - from) / t_max;
        bool expected = false;
        for (const Sphere& s : spheres) {
            if (!s.casts_shadow) continue;
            const Vec3 oc = from - s.center;
            if (dot(oc, oc) - s.radius * s.radius * k_own_sphere <= 0.0f) continue;
            const float b = dot(oc, dir), disc = b * b - (dot(oc, oc) - s.radius * s.radius);
            expected |= b < 0.0f && disc > 0.0f && -b - std::sqrt(disc) < t_max;
        }
        EXPECT_EQ(occluders.blocks_segment(from, dir, t_max), expected) << "trial " << trial;
        blocked += expected ? 1 : 0;
    }
    EXPECT_GT(blocked, 100);  // the check saw both answers
    EXPECT_LT(blocked, 1900);
}

}  // namespace
}  // namespace hikari
