#include "hikari/core/aabb.h"

#include <gtest/gtest.h>

namespace hikari {
namespace {

TEST(Aabb, DefaultIsEmptyAndExtendingItYieldsThePoint) {
    Aabb box;
    EXPECT_TRUE(box.empty());
    EXPECT_EQ(box.half_area(), 0.0f);
    box.extend(Vec3(1, 2, 3));
    EXPECT_FALSE(box.empty());
    EXPECT_EQ(box, Aabb::from_point({1, 2, 3}));
}

TEST(Aabb, HalfAreaOfUnitCubeIsThree) {
    Aabb box = Aabb::from_point({0, 0, 0});
    box.extend(Vec3(1, 1, 1));
    EXPECT_EQ(box.half_area(), 3.0f);
    EXPECT_EQ(box.center(), Vec3(0.5f));
}

TEST(Aabb, MergeContainsBoth) {
    const Aabb a{{0, 0, 0}, {1, 1, 1}};
    const Aabb b{{-1, 0.5f, 0}, {0.5f, 3, 0.5f}};
    const Aabb m = merge(a, b);
    EXPECT_TRUE(m.contains(a));
    EXPECT_TRUE(m.contains(b));
    EXPECT_FALSE(a.contains(m));
    EXPECT_EQ(m.largest_axis(), 1);
}

}  // namespace
}  // namespace hikari
