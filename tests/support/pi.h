#pragma once
// π for the tests' analytic answers, in the precision each computation is written in.

#include <numbers>

namespace hikari::testing {

inline constexpr double k_pi = std::numbers::pi;
inline constexpr float k_pi_f = std::numbers::pi_v<float>;

}  // namespace hikari::testing
