#pragma once
// The nearest hits of a whole block of camera rays at once: the front end of the Whitted ray
// tracer (whitted.cpp), which then shades each pixel from its hit.
//
// Why a block: camera rays through neighbouring pixels share their origin and nearly their
// direction (Wald, Slusallek, Benthin & Wagner 2001, "Interactive Rendering with Coherent Ray
// Tracing"), so they are cheapest found together: triangles through the wide BVH as 4x4 packets
// (ray/wide_bvh_packet.h), spheres and planes one primitive at a time against all rays of the
// block in SIMD lanes (Boulos et al. 2007, "Packet-based Whitted and Distribution Ray Tracing",
// which packets the camera rays of a Whitted tracer the same way). The answers are exactly those
// of generating each ray with camera_ray and asking SceneIntersector::closest: same primitive,
// bit-identical t, position and normals, at every SIMD level (the lane loops perform the scalar
// code's operations in the scalar code's order, without FMA contraction).

#include <cstdint>
#include <vector>

#include "hikari/core/ray.h"
#include "hikari/ray/scene_intersector.h"
#include "hikari/ray/simd_level.h"
#include "hikari/scene/camera.h"

namespace hikari {

/// Edge of the largest block of camera rays traced at once, in pixels.
inline constexpr int k_primary_block = 16;
/// Rays in a full block.
inline constexpr int k_primary_block_rays = k_primary_block * k_primary_block;
/// Lanes the kernels compute together: their loops run over whole chunks (a constant trip count,
/// which is what lets g++ vectorise them), only as many chunks as hold rays.
inline constexpr int k_lane_chunk = 16;
/// Lanes that hold `count` rays: count rounded up to whole chunks.
constexpr int lanes_for(int count) {
    return (count + k_lane_chunk - 1) / k_lane_chunk * k_lane_chunk;
}
/// The most lights whose shadow rays a block traces (one bit each in PrimaryBlock::lit).
inline constexpr size_t k_max_block_lights = 8;

/// The camera rays of a block of at most 16 x 16 pixels and their nearest hits, row-major with
/// a row stride of k_primary_block: entry y * k_primary_block + x is pixel (x0 + x, y0 + y).
struct PrimaryBlock {
    Ray rays[k_primary_block_rays];         ///< the ray through each pixel centre
    SurfaceHit hits[k_primary_block_rays];  ///< its nearest hit, where found
    uint8_t found[k_primary_block_rays];    ///< 1 where the ray hits something (t in (0, ∞))
    /// Where found and `shadows_known`: bit l set when the shadow ray of the hit toward light l
    /// (from offset_ray_origin(position, geometric normal facing the ray), as shade_local
    /// builds it) is unblocked, as SceneIntersector::occluded answers.
    uint8_t lit[k_primary_block_rays];
    bool shadows_known = false;  ///< false: `lit` not filled (more than k_max_block_lights)
};

namespace detail {
/// The scene's spheres and planes as the kernels read them: plain arrays, one entry per
/// primitive (no library code runs inside the kernels).
struct PrimaryAnalytic {
    const float* sphere_center[3];
    const float* sphere_radius;
    int32_t spheres;
    const float* plane_point[3];
    const float* plane_normal[3];
    int32_t planes;
};

struct PrimaryLanes;

/// One light as the shadow kernel reads it.
struct PrimaryShadowLight {
    bool directional;
    float position[3];  ///< point lights
    float to_light[3];  ///< directional lights: the unit direction toward the light
};

}  // namespace detail

/// Traces the camera rays of pixel blocks of one scene and camera. Built once per render
/// (the scene's spheres and planes copied into the lanes' layout), read by all threads.
class PrimaryHitTracer {
  public:
    /// `intersector` (and the scene it reads) must outlive this object. `level` must be
    /// supported by this CPU; every level gives the same answers.
    PrimaryHitTracer(const SceneIntersector& intersector, const Scene& scene,
                     const CameraFrame& frame, SimdLevel level = best_simd_level());

    /// Fills `block` for the pixels [x0, x0 + width) x [y0, y0 + height) (width, height at most
    /// k_primary_block, inside the image): the ray camera_ray(frame, x + 0.5, y + 0.5) through
    /// each, its nearest hit inside (0, ∞) as SceneIntersector::closest reports it, and which
    /// lights each hit sees (the shadow rays of the hits traced together too).
    void trace(int x0, int y0, int width, int height, PrimaryBlock& block) const;

    /// The same for any rays (a Whitted tracer's mirror and refracted rays): block.rays[0,
    /// count) are given (count at most k_primary_block_rays, unit directions), and entry i of
    /// hits, found and lit is filled for each, as trace() fills them; entries past `count` get
    /// found = 0. Triangles are found one ray at a time (such rays are rarely coherent).
    void trace_rays(int count, PrimaryBlock& block) const;

  private:
    /// Spheres and planes in structure-of-arrays form, one entry per primitive, for the lanes.
    struct Analytic {
        std::vector<float> sphere_center[3], sphere_radius;
        std::vector<float> plane_point[3], plane_normal[3];

        void add(const Sphere& s);
        void add(const Plane& p);
        /// The kernels' view of these arrays.
        detail::PrimaryAnalytic view() const;
    };

    /// Steps shared by trace() and trace_rays(): spheres and planes after the triangles already
    /// in `lanes`, each hit described into `block`, and the hits' shadow rays, for the lanes
    /// [0, lanes_for(count)). `valid(i)` says whether lane i is a ray of the block.
    template <class ValidLane>
    void finish(detail::PrimaryLanes& lanes, const TriangleHit* triangle_hits, int count,
                ValidLane valid, PrimaryBlock& block) const;

    const SceneIntersector& m_intersector;
    const Scene& m_scene;
    CameraFrame m_frame;
    SimdLevel m_level;
    Analytic m_analytic;
    Analytic m_casters;  ///< the spheres and planes that cast shadows
    std::vector<detail::PrimaryShadowLight> m_lights;
};

namespace detail {

/// What the lane kernels (primary_hits_kernel.h) read and write for one block. Lane i is pixel
/// (x0 + i % 16, y0 + i / 16) for camera rays, entry i of the block for trace_rays(). The kernels
/// compute whole chunks of k_lane_chunk lanes, so the lanes past the last ray in its chunk hold
/// harmless finite rays, never read back.
struct alignas(64) PrimaryLanes {
    float origin[3][k_primary_block_rays];     ///< ray origin per lane
    float direction[3][k_primary_block_rays];  ///< unit ray direction per lane
    float t[k_primary_block_rays];             ///< in: nearest triangle t or ∞; out: nearest t
    /// in: 0 none, 1 triangle; out: also 2 + i for sphere i, 2 + spheres + j for plane j.
    int32_t object[k_primary_block_rays];
};

/// Camera parameters the kernel needs, as plain floats.
struct PrimaryCamera {
    float eye[3], right[3], up[3], forward[3];
    float tan_half_fov_y, aspect, width, height;
    int x0, y0;
};

/// The shadow rays of a block's hits toward one light, lane by lane.
struct alignas(64) ShadowLanes {
    float position[3][k_primary_block_rays];  ///< in: hit point
    float normal[3][k_primary_block_rays];    ///< in: geometric normal facing the camera ray
    float origin[3][k_primary_block_rays];    ///< out: shadow-ray origin, offset off the surface
    float to_light[3][k_primary_block_rays];  ///< out: unit direction toward the light
    float distance[k_primary_block_rays];     ///< out: distance to the light (∞: directional)
    int32_t blocked[k_primary_block_rays];    ///< out: 1 where a casting sphere or plane blocks
};

/// Camera rays of a block, without hits yet (kernel for each SIMD level).
void primary_directions_portable(const PrimaryCamera& cam, PrimaryLanes& lanes);
void primary_directions_avx2(const PrimaryCamera& cam, PrimaryLanes& lanes);
void primary_directions_avx512(const PrimaryCamera& cam, PrimaryLanes& lanes);
/// Spheres and planes against lanes [0, lanes_for(count)), after the triangles (kernel for
/// each SIMD level). Lanes past `count` must hold a harmless finite ray.
void primary_analytic_portable(const PrimaryAnalytic& a, int count, PrimaryLanes& lanes);
void primary_analytic_avx2(const PrimaryAnalytic& a, int count, PrimaryLanes& lanes);
void primary_analytic_avx512(const PrimaryAnalytic& a, int count, PrimaryLanes& lanes);

/// Shadow rays of lanes [0, lanes_for(count)) toward one light against the casting spheres and
/// planes (each SIMD level).
void primary_shadows_portable(const PrimaryShadowLight& light, const PrimaryAnalytic& casters,
                              int count, ShadowLanes& lanes);
void primary_shadows_avx2(const PrimaryShadowLight& light, const PrimaryAnalytic& casters,
                          int count, ShadowLanes& lanes);
void primary_shadows_avx512(const PrimaryShadowLight& light, const PrimaryAnalytic& casters,
                            int count, ShadowLanes& lanes);

}  // namespace detail

}  // namespace hikari
