#pragma once
// Which texture kinds SIMD lanes evaluate themselves.

namespace hikari {

/// Whether texture kind T has a lane form: its texture_colour works for packs of lanes
/// (core/lanes.h). False unless the kind's file says so; lanes meeting a kind without one are
/// shaded by the scalar code instead, so a new kind works everywhere from its scalar form alone.
template <class T>
inline constexpr bool k_texture_has_lane_form = false;

}  // namespace hikari
