#pragma once
// The shading step of the Whitted ray tracer for a whole block of hits at once: the lecture's
// shading model (Fig 4.29, shading/phong.h) at each hit, then the mirror and refracted rays it
// spawns (Fig 4.43, shading/refraction.h), in SIMD lanes. whitted.cpp runs it level by level
// over a tile's rays (a breadth-first "wavefront" of the ray tree, as in Boulos et al. 2007,
// "Packet-based Whitted and Distribution Ray Tracing") instead of recursing one ray at a time.
//
// The lanes perform the scalar code's operations (shade_local / shade_direct / phong_power /
// textured / reflect / refract / offset_ray_origin) in the same order without FMA contraction,
// so every level gives bit-identical colours and rays; tests compare them with the recursive
// tracer. The one exception, a Phong exponent that is not an integer in [0,
// k_max_integer_exponent], is flagged per lane for the caller to shade with the scalar code
// (std::pow has no exact lane form).

#include <bit>
#include <cstdint>
#include <vector>

#include "hikari/core/block_lanes.h"
#include "hikari/core/simd_level.h"
#include "hikari/scene/scene.h"
#include "hikari/shading/phong.h"

namespace hikari {

namespace detail {

/// Lanes per shading call: one block of rays (integrators/whitted/primary_hits.h).
inline constexpr int k_shade_lanes = k_primary_block_rays;
static_assert(k_shade_lanes % k_lane_chunk == 0);
/// Squaring steps of phong_power for any exponent up to k_max_integer_exponent.
inline constexpr int k_exponent_bits =
    std::bit_width(static_cast<unsigned>(k_max_integer_exponent));

/// The scene's materials as the lanes read them: structure-of-arrays, indexed by material.
struct ShadeMaterials {
    const float* ka[3];
    const float* kd[3];
    const float* ks[3];
    /// The Phong exponent when it is an integer in [0, k_max_integer_exponent] (phong_power's
    /// repeated squaring), else -1 (the lane is flagged scalar_specular).
    const int32_t* exponent;
    const float* reflectivity;
    const float* transparency;
    const float* ior;
    const int32_t* textured;  ///< 1: ka and kd are scaled by the checker texture
    const float* inverse_size;
    const float* offset[3];
    const float* color_a[3];
    const float* color_b[3];
};

/// One light as the lanes read it (sample_light's two cases).
struct ShadeLight {
    int32_t directional;     ///< 1: directional light, else point light
    int32_t inverse_square;  ///< point lights: 1 when irradiance falls off as 1/d²
    float position[3];       ///< point lights
    float to_light[3];       ///< directional lights: the unit direction toward the light
    float intensity[3];
};

/// Everything the shading lanes read besides the hits.
struct ShadeScene {
    ShadeMaterials materials;
    const ShadeLight* lights;
    int32_t light_count;  ///< at most k_max_block_lights (one bit each in BlockLanes::lit)
    float ambient[3];
    /// What rays that hit nothing see (Sky::colour): the gradient when `gradient`, else the
    /// background colour.
    int32_t gradient;
    float horizon[3], zenith[3], background[3];
};

/// The shading kernel for each SIMD level: fills the outputs (LaneChunk's "shading's results")
/// of every active lane of the chunks that hold one of the first `count` lanes, and the
/// secondary rays when `spawn` is nonzero. Lanes without a hit get only their colour: the sky's.
void shade_lanes_portable(const ShadeScene& scene, int spawn, int count, BlockLanes& lanes);
void shade_lanes_avx2(const ShadeScene& scene, int spawn, int count, BlockLanes& lanes);
void shade_lanes_avx512(const ShadeScene& scene, int spawn, int count, BlockLanes& lanes);

}  // namespace detail

/// A scene's materials and lights copied into the lanes' layout once per render, and the kernel
/// of the chosen SIMD level. Read by all threads.
class LaneShader {
  public:
    /// `scene` must outlive this object; `level` must be supported by this CPU.
    explicit LaneShader(const Scene& scene, SimdLevel level = best_simd_level());

    /// Whether the lanes can shade this scene (at most k_max_block_lights lights); else use the
    /// scalar code.
    bool supported() const { return m_supported; }
    /// Shades every active lane among the first round_up(count, k_lane_chunk) of `lanes` (and
    /// spawns their secondary rays when `spawn`); the lanes past `count` in the last chunk must
    /// be marked inactive.
    void shade(detail::BlockLanes& lanes, int count, bool spawn) const;

  private:
    std::vector<float> m_floats;  ///< backing store of the material columns
    std::vector<int32_t> m_ints;
    std::vector<detail::ShadeLight> m_lights;
    detail::ShadeScene m_scene{};
    SimdLevel m_level;
    bool m_supported = true;
};

}  // namespace hikari
