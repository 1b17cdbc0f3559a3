#include "hikari/integrators/whitted/whitted_shade.h"

#include "hikari/integrators/whitted/whitted_shade_kernel.h"

namespace hikari {

namespace detail {

void shade_lanes_portable(const WhittedScene& scene, int spawn, int count, BlockLanes& lanes) {
    shade_kernel(scene, spawn, count, lanes);
}

}  // namespace detail

void LaneShader::shade(detail::BlockLanes& lanes, int count, bool spawn) const {
    simd_pick(m_level, detail::shade_lanes_portable, detail::shade_lanes_avx2,
              detail::shade_lanes_avx512)(m_scene, spawn ? 1 : 0, count, lanes);
}

}  // namespace hikari
