#pragma once
// Comparing vectors in tests, component by component.

#include <gtest/gtest.h>

#include "hikari/core/vec.h"

namespace hikari::testing {

/// Expects each component of `a` within `tolerance` of the same component of `b`.
inline void expect_near(Vec3 a, Vec3 b, float tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

}  // namespace hikari::testing
