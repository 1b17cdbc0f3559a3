#pragma once
// What every rendering method takes besides the scene and its own settings: the channel through
// which a render reports progress and learns that it should stop, the statistics it reports, and
// which buffers the caller needs.

#include <atomic>
#include <cstdint>

namespace hikari {

class BuildCache;
struct TileShare;

/// Progress and cancellation of one render, shared between the render and its caller.
struct RenderControl {
    std::atomic<uint64_t> work_done{0};   ///< units (tiles, primitives) finished so far
    std::atomic<uint64_t> work_total{0};  ///< units in all, set by the method when it starts
    std::atomic<bool> cancel{false};      ///< set by the caller (e.g. on SIGINT) to stop early
    /// The camera's tiles this process renders when processes share the image (frame/
    /// tile_share.h); null: all of them. Set only for methods that declare Method::shares_tiles.
    const TileShare* share = nullptr;
};

/// Figures a render reports for `hikari render --stats`; a method that has none leaves them 0.
struct RenderStats {
    std::atomic<uint64_t> rays_traced{0};   ///< camera, secondary and shadow rays
    std::atomic<uint64_t> paths_traced{0};  ///< path tracing: camera samples traced
    /// Path tracing: samples whose radiance came out NaN or infinite, left out of the image.
    std::atomic<uint64_t> bad_samples{0};
    std::atomic<uint64_t> bvh_triangles{0};     ///< triangles in the BVH
    std::atomic<uint64_t> bvh_nodes{0};         ///< wide BVH nodes
    std::atomic<uint64_t> bvh_bytes{0};         ///< BVH nodes + triangle data + ids
    std::atomic<uint64_t> bvh_build_us{0};      ///< BVH build wall time, microseconds
    std::atomic<uint64_t> bvh_reused{0};        ///< 1: the BVH was kept from an earlier render
    std::atomic<uint64_t> bvh_spheres{0};       ///< spheres in the sphere BVH
    std::atomic<uint64_t> bvh_sphere_nodes{0};  ///< its wide nodes
    std::atomic<uint64_t> bvh_sphere_bytes{0};  ///< its nodes + sphere data + ids
    // Raster methods (raster/vertex_pipeline.h VertexStageCounts and the visibility passes).
    std::atomic<uint64_t> raster_triangles{0};     ///< tessellated triangles into the vertex stage
    std::atomic<uint64_t> raster_culled{0};        ///< back faces dropped
    std::atomic<uint64_t> raster_clipped_away{0};  ///< wholly outside the clip volume
    std::atomic<uint64_t> raster_cut{0};           ///< cut by a clip plane, kept in pieces
    std::atomic<uint64_t> raster_screen_triangles{0};  ///< after clipping
    std::atomic<uint64_t> raster_exact_spheres{0};  ///< spheres drawn per pixel (sphere_raster.h)
    /// Z-buffer: fragments depth-tested; depth sort: pixels painted; scanline: sample spans.
    std::atomic<uint64_t> raster_fragments{0};
    std::atomic<uint64_t> raster_covered_pixels{0};  ///< pixels that show a triangle
    std::atomic<uint64_t> depth_sort_splits{0};      ///< polygons cut by the depth sort
    /// Polygons in the depth sort's painting order (each piece of a split polygon one).
    std::atomic<uint64_t> depth_sort_polygons{0};
    /// The raster methods' shadow pass before shading (maps, volumes or the analytic occluders),
    /// apart from the render of the picture: its wall time, and the map faces and their texels
    /// it drew (a point light's cube map is up to six faces) or the shadow-volume stencils it
    /// counted; the maps a render session kept from an earlier render are not drawn again.
    std::atomic<uint64_t> shadow_pass_us{0};
    std::atomic<uint64_t> shadow_map_faces{0};
    std::atomic<uint64_t> shadow_map_texels{0};
    std::atomic<uint64_t> shadow_maps_kept{0};  ///< lights' maps kept from an earlier render
    std::atomic<uint64_t> shadow_volume_stencils{0};
    /// 1: the depth sort ran out of cuts (raster/depth_sort.h, DepthSortCounts::gave_up).
    std::atomic<uint64_t> depth_sort_gave_up{0};
};

/// How a method decides whether a light reaches a point (`--shadows`, the lecture's Fig 4.24).
enum class ShadowMode {
    none,      ///< every light reaches every point that faces it
    ray,       ///< a shadow ray toward the light (ray tracing)
    map,       ///< a Z-buffer seen from the light (shadow mapping, raster/shadow_map.h)
    volume,    ///< shadow volumes counted in a stencil buffer
    pcf,       ///< shadow maps filtered by percentage-closer filtering (Reeves et al. 1987)
    pcss,      ///< percentage-closer soft shadows (Fernando 2005)
    analytic,  ///< area lights: the visible part of the light in closed form (Nishita & Nakamae)
};

/// Samples per area or environment light per shaded point (`--light-samples`) unless given.
inline constexpr int k_default_light_samples = 16;

/// Settings every method takes; each method's own (integrators/whitted/whitted.h,
/// raster/raster_settings.h) come beside them.
struct RenderSettings {
    RenderControl* control = nullptr;  ///< optional progress / cancellation
    RenderStats* stats = nullptr;      ///< optional statistics
    /// Fill the framebuffer's depth, id and normal buffers too. False: colour only (ray tracing
    /// then neither allocates nor writes them; raster methods, which need depth, keep them).
    bool aov_buffers = true;
    /// What earlier renders of the same scene built and kept (core/build_cache.h; a render
    /// session's); null: the render builds what it needs for itself.
    BuildCache* cache = nullptr;
};

}  // namespace hikari
