#pragma once
// The nearest hits of a whole block of rays at once, described in the block's lanes
// (core/block_lanes.h), with their shadow rays: the front end of the Whitted ray tracer
// (whitted.cpp), which then shades the hits where they lie (integrators/whitted/whitted_shade.h).
//
// Why a block: camera rays through neighbouring pixels share their origin and nearly their
// direction (Wald, Slusallek, Benthin & Wagner 2001, "Interactive Rendering with Coherent Ray
// Tracing"), so they are cheapest found together: triangles through the wide BVH as 4x4 packets
// (bvh/wide_bvh_packet.h), planes and a few spheres one primitive at a time against all rays of
// the block in SIMD lanes (Boulos et al. 2007, "Packet-based Whitted and Distribution Ray
// Tracing", which packets the camera rays of a Whitted tracer the same way), many spheres one ray
// at a time through their BVH (bvh/sphere_bvh.h). The answers are exactly those of generating each
// ray with camera_ray and asking SceneIntersector::closest: same primitive, bit-identical t,
// position and normals, at every SIMD level (the lane loops perform the scalar code's operations in
// the scalar code's order, without FMA contraction).

#include <cstdint>
#include <vector>

#include "hikari/bvh/scene_intersector.h"
#include "hikari/core/block_lanes.h"
#include "hikari/core/ray.h"
#include "hikari/core/simd_level.h"
#include "hikari/scene/camera.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// The rays of a block (at most 16 x 16 camera rays, or any k_primary_block_rays rays) and their
/// nearest hits, in lanes (core/block_lanes.h). For camera rays, lane y * k_primary_block + x is
/// pixel (x0 + x, y0 + y).
struct PrimaryBlock {
    detail::BlockLanes lanes;
    /// Chunks of `lanes` that hold rays (camera rays: the block's rows); the others hold none.
    int chunks = 0;
    /// Where a hit and `shadows_known`: bit l of lit set when the shadow ray of the hit toward
    /// light l (from offset_ray_origin(position, geometric normal facing the ray), as
    /// shade_local builds it) is unblocked, as SceneIntersector::occluded answers.
    bool shadows_known = false;  ///< false: `lit` not filled (more than k_max_block_lights)
    int32_t spheres = 0;         ///< the scene's sphere count (decodes LaneChunk::object)

    /// Whether lane k's ray hits something (t in (0, ∞)).
    bool found(int k) const { return lanes.chunk(k).active[detail::lane_in_chunk(k)] != 0; }
    /// Lane k's ray.
    Ray ray(int k) const;
    /// Lane k's nearest hit, where found.
    SurfaceHit hit(int k) const;
    /// Lane k's shadow answers (bit l: light l unblocked), where found and shadows_known.
    uint32_t lit(int k) const {
        return static_cast<uint32_t>(lanes.chunk(k).lit[detail::lane_in_chunk(k)]);
    }
};

namespace detail {
/// The scene's spheres and planes as the kernels read them: plain arrays, one entry per
/// primitive (no library code runs inside the kernels).
struct PrimaryAnalytic {
    const float* sphere_center[3];
    const float* sphere_radius;
    int32_t spheres;
    /// Object codes the scene's spheres take: plane p is code 2 + sphere_codes + p. The scene's
    /// sphere count, also when its spheres are not in these arrays but in the BVH.
    int32_t sphere_codes;
    const float* plane_point[3];
    const float* plane_normal[3];
    int32_t planes;
};

/// What describing a hit reads per object code (LaneChunk::object): for spheres the centre and
/// 1 / radius, for planes the normal, and every object's material and id. Codes 0 (no hit) and
/// 1 (triangle, described one lane at a time) hold zeros.
struct PrimaryObjects {
    const int32_t* is_sphere;
    const float* center[3];
    const float* inverse_radius;
    const float* normal[3];
    const int32_t* material;
    const uint32_t* id;
};

}  // namespace detail

/// Whether some primitive of `scene` casts a shadow: where none does (`--shadows none`), a shadow
/// ray cannot be blocked, and the ray tracer traces (and counts) none.
inline bool casts_any_shadow(const Scene& scene) {
    for (const Sphere& s : scene.spheres)
        if (s.casts_shadow) return true;
    for (const Plane& p : scene.planes)
        if (p.casts_shadow) return true;
    if (scene.triangles.casts_shadow.empty()) return !scene.triangles.indices.empty();
    for (const uint8_t casts : scene.triangles.casts_shadow)
        if (casts != 0) return true;
    return false;
}

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

    /// The same for any rays (a Whitted tracer's mirror and refracted rays): `rays[0, count)`
    /// (count in [1, k_primary_block_rays], unit directions) go to lanes [0, count) of `block`,
    /// each with its hit and lit filled as trace() fills them; the rest of the last chunk holds
    /// no hit. Triangles are found one ray at a time (such rays are rarely coherent).
    void trace_rays(const Ray* rays, int count, PrimaryBlock& block) const;

  private:
    /// Spheres and planes in structure-of-arrays form, one entry per primitive, for the lanes.
    struct Analytic {
        std::vector<float> sphere_center[3], sphere_radius;
        std::vector<float> plane_point[3], plane_normal[3];
        int32_t sphere_codes = 0;

        void add(const Sphere& s);
        void add(const Plane& p);
        /// The kernels' view of these arrays.
        detail::PrimaryAnalytic view() const;
    };

    /// Per object code, what describing a hit reads (detail::PrimaryObjects).
    struct Objects {
        std::vector<int32_t> is_sphere, material;
        std::vector<float> center[3], inverse_radius, normal[3];
        std::vector<uint32_t> id;

        void add(int32_t sphere, Vec3 center, float inverse_radius, Vec3 normal, uint32_t material,
                 PrimitiveId id);
        detail::PrimaryObjects view() const;
    };

    /// Steps shared by trace() and trace_rays() once every lane's nearest hit is known (object 0
    /// in lanes that hold no ray): each hit described, and the hits' shadow rays.
    void finish(const TriangleHit* triangle_hits, PrimaryBlock& block) const;
    /// Where the spheres live in the BVH: lane k's nearest sphere nearer than its hit so far.
    void find_spheres(int k, PrimaryBlock& block) const;
    /// Where the spheres live in the BVH: whether one blocks lane j's shadow ray in `chunk`.
    bool sphere_blocks_shadow(const detail::LaneChunk& chunk, int j) const;

    const SceneIntersector& m_intersector;
    const Scene& m_scene;
    CameraFrame m_frame;
    SimdLevel m_level;
    /// The spheres are few enough to be tested one at a time against all rays of a block, in
    /// the lanes; otherwise each ray asks the sphere BVH (the same answers, found faster).
    bool m_spheres_in_lanes = true;
    Analytic m_analytic;
    Analytic m_casters;           ///< the spheres and planes that cast shadows
    bool m_casts_shadows = true;  ///< some primitive casts a shadow (casts_any_shadow)
    Objects m_objects;
};

namespace detail {

/// Camera parameters the kernel needs, as plain floats.
struct PrimaryCamera {
    float eye[3], right[3], up[3], forward[3];
    float tan_half_fov_y, aspect, width, height;
    int x0, y0;
};

// The kernels for each SIMD level; each works on the first `chunks` chunks of `lanes`.

/// Camera rays of a block, one chunk per row, without hits yet (t = ∞, object 0).
void primary_directions_portable(const PrimaryCamera& cam, int chunks, BlockLanes& lanes);
void primary_directions_avx2(const PrimaryCamera& cam, int chunks, BlockLanes& lanes);
void primary_directions_avx512(const PrimaryCamera& cam, int chunks, BlockLanes& lanes);
/// Spheres and planes after the triangles (t, object). Every lane must hold a finite ray.
void primary_analytic_portable(const PrimaryAnalytic& a, int chunks, BlockLanes& lanes);
void primary_analytic_avx2(const PrimaryAnalytic& a, int chunks, BlockLanes& lanes);
void primary_analytic_avx512(const PrimaryAnalytic& a, int chunks, BlockLanes& lanes);
/// Each lane's hit described from its t and object (active, position, normals, material, id;
/// zeros where no hit). Triangle hits get only active and a position, to be described apart.
void primary_describe_portable(const PrimaryObjects& o, int chunks, BlockLanes& lanes);
void primary_describe_avx2(const PrimaryObjects& o, int chunks, BlockLanes& lanes);
void primary_describe_avx512(const PrimaryObjects& o, int chunks, BlockLanes& lanes);
/// The hits' shadow rays toward one light against the casting spheres and planes (shadow_*
/// and blocked), in the chunks that hold a hit.
void primary_shadows_portable(const Light& light, const PrimaryAnalytic& casters, int chunks,
                              BlockLanes& lanes);
void primary_shadows_avx2(const Light& light, const PrimaryAnalytic& casters, int chunks,
                          BlockLanes& lanes);
void primary_shadows_avx512(const Light& light, const PrimaryAnalytic& casters, int chunks,
                            BlockLanes& lanes);

}  // namespace detail

}  // namespace hikari
