#pragma once
// The pack tag of the tests (core/lanes.h): packs of `Width` lanes, compiled for the tests'
// baseline target, where the wider ones are split into SSE registers.

namespace hikari::testing {

template <int Width>
struct TestIsa {
    static constexpr int k_width = Width;
};

}  // namespace hikari::testing
