#pragma once
// Caustics by light tracing. A path tracer finds a caustic (light that reaches a diffuse surface
// through a mirror or glass: L S D ... E in Heckbert's notation) only when a direction drawn
// from the diffuse surface happens to hit the mirror or glass at the one angle that leads on to
// the light; light sampling cannot aim through them. With a small bright light such paths are
// rare and very bright: fireflies. Traced from the light instead (Arvo 1986, "Backward ray
// tracing"; Veach 1997, §10.2, the t = 1 strategy of bidirectional path tracing), the same paths
// are easy: the light's own direction reaches the mirror or glass, the path bounces on and each
// diffuse point it meets is joined to the eye.
//
// The two tracers share the work by splitting the paths between them, so nothing is counted
// twice and nothing is lost (both are unbiased, so their sum is): a path belongs to the light
// tracer when it starts at an emissive triangle, its vertex next to the light scatters by a
// delta lobe (mirror or glass) and its vertex seen by the eye by a smooth lobe (Lambert or
// Phong); every other path stays the path tracer's. Docs: docs/path-tracing.md.

#include <atomic>
#include <cstdint>
#include <vector>

#include "hikari/bvh/scene_intersector.h"
#include "hikari/core/vec.h"
#include "hikari/frame/pixel_filter.h"
#include "hikari/scene/camera.h"
#include "hikari/scene/scene.h"
#include "hikari/shading/bsdf/scattering.h"
#include "hikari/shading/material_eval.h"

namespace hikari {

/// The material at `hit` (texture and vertex colours applied), seen from `at`.
MaterialSample<float> material_at_hit(const Scene& scene, const SceneIntersector& intersector,
                                      const SurfaceHit& hit, const ScatterFrame& at);

/// Whether `scene` has caustic paths for the light tracer to take: a perspective camera, an
/// emissive triangle and a material with a mirror or glass lobe.
bool traces_caustics_from_lights(const Scene& scene);

struct TileShare;

/// The light tracer's half of an image: its light paths' contributions summed per pixel.
class CausticLightTracer {
  public:
    /// `scale`: each material's energy_scale (the path tracer's); `filter`: the pixel filter the
    /// camera's samples are drawn with; `max_depth`: the path tracer's bounces (a path has at
    /// most that many vertices between the light and the eye).
    CausticLightTracer(const Scene& scene, const SceneIntersector& intersector,
                       const std::vector<float>& scale, const PixelFilter& filter, int max_depth);

    /// Traces light paths [first, first + count), adding their contributions to the sums; with
    /// a share, only this process's runs of paths (frame/tile_share.h).
    void trace(uint64_t first, uint64_t count, uint64_t& rays, const TileShare* share = nullptr);

    /// Makes the sums those of every process's paths (TileShare::sum_over_parts).
    void sum_over_parts(const TileShare& share);

    /// Pixel `i`'s sum of contributions, to be divided by the number of light paths traced.
    Vec3 sum(size_t i) const;

  private:
    void trace_path(uint64_t index, uint64_t& rays);
    /// Joins the surface point `x` (its frame `at`, its BSDF) to the eye with throughput `beta`.
    void connect_to_eye(Vec3 x, const ScatterFrame& at, const Scattering& bsdf, Vec3 beta,
                        uint64_t& rays);
    void splat(Vec2 image_point, Vec3 value);

    const Scene& m_scene;
    const SceneIntersector& m_intersector;
    const std::vector<float>& m_scale;
    const PixelFilter& m_filter;
    int m_max_depth;
    CameraFrame m_frame;
    float m_pixel_area;                 ///< a pixel's area on the image plane one unit from the eye
    float m_filter_volume;              ///< ∫∫ f1(x) f1(y): the filter's normalization
    std::vector<uint32_t> m_triangles;  ///< the emissive triangles
    std::vector<double> m_cdf;          ///< running sum of their powers
    /// Fixed-point sums (k_fixed_scale per unit), so the order the threads add in cannot change
    /// a bit of the result: the image stays the same for any thread count.
    std::vector<std::atomic<int64_t>> m_fixed;
};

}  // namespace hikari
