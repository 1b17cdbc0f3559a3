#pragma once
// Shadow mapping (Williams 1978, "Casting curved shadows on curved surfaces"), the lecture's
// shadow as hidden-surface removal seen from the light (Fig 4.24), in its two steps: (1) a
// Z-buffer rendered from a camera at the light, by the same vertex stage and Z-buffer as the
// image; (2) when shading, a point is lit when it is no farther from the light than the depth
// the map holds in its direction.

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "hikari/core/aabb.h"
#include "hikari/core/build_cache.h"
#include "hikari/core/huge_page_allocator.h"
#include "hikari/frame/render_settings.h"
#include "hikari/raster/raster_scene.h"
#include "hikari/raster/shadow_map_lookup.h"
#include "hikari/raster/vertex_pipeline.h"
#include "hikari/scene/scene.h"
#include "hikari/shading/light_shadow_view.h"

namespace hikari {

/// One depth image seen from a light.
struct ShadowMapFace {
    RasterView view;       ///< the light's camera (size × size, perspective or orthographic)
    Mat4 world_from_clip;  ///< the inverse of view.clip_from_world, to cast texel rays
    /// Per texel, row-major from the top: the depth of the nearest shadow caster along the ray
    /// through the texel's centre (distance from a point light; distance along a directional
    /// light's rays from the map's reference point), +infinity where no caster is seen. Empty
    /// when no caster lies in the face's view (a cube map's faces away from every caster): the
    /// face is then not drawn at all. Huge pages, left unwritten until the face is drawn: faulting
    /// in 16 MiB of 4 KiB pages for a 2048² face costs more than drawing it
    /// (core/huge_page_allocator.h).
    std::vector<float, UninitializedHugePageAllocator<float>> depth;
};

/// The map of one light (its shadow_view, shading/lights.h): one orthographic face for a
/// directional light, six 90° faces (a cube map) around a point light, one perspective face
/// over a spot light's cone.
struct LightShadowMap {
    bool directional = false;
    bool cone = false;  ///< one perspective face from `origin` along `direction`
    Vec3 origin;        ///< the light's position; the reference point of a directional map
    Vec3 direction;     ///< a directional light's unit travel direction; a cone's unit axis
    int size = 0;       ///< texels per side of every face
    /// World size of one texel: of a directional map everywhere; of a cube or cone map at
    /// distance 1 from the light, on its axes (it grows in proportion to the distance).
    float texel_size = 0;
    std::vector<ShadowMapFace> faces;
};

/// The maps of a scene's lights, index for index (null where a light casts no shadow map:
/// nothing casts shadows in its light). Shared: a render session keeps each light's map for the
/// renders after it (shadow_maps_for_render).
struct ShadowMaps {
    std::vector<std::shared_ptr<const LightShadowMap>> lights;
};

/// Shadow maps drawn once and shared by the passes of one supersampled render.
struct SharedShadowMaps {
    std::shared_ptr<const ShadowMaps> maps;  ///< null until the first pass draws them
};

/// Which triangles of `raster` (the tessellated scene) cast shadows into maps: those of
/// spheres, triangles and meshes whose `casts_shadow` is true. Infinite planes are left out of
/// every map — no finite map holds them; plane_blocks_light() answers for them exactly.
std::vector<uint8_t> shadow_casting_triangles(const Scene& scene, const RasterScene& raster);

/// Refuses (InputError, core/memory_budget.h) shadow maps of `size` × `size` texels per face
/// for `scene`'s lights (one face per directional light, six per point or area light) that
/// would not fit in the memory limit, before any is drawn: what build_shadow_maps checks first.
void check_shadow_map_memory(const Scene& scene, const RasterScene& raster, int size);

/// Draws a face's depth keys, width × height row-major: what zbuffer_draw(triangles, width,
/// height, …, nullptr, depth) writes, by another Z-buffer that gives the same buffer (the
/// kernels of raster/zbuffer_kernels.h, on the GPU). Null: the CPU's Z-buffer draws.
using FaceDepthDrawer = std::function<void(std::span<const ScreenTriangle> triangles, int width,
                                           int height, float* depth)>;

/// Renders the shadow maps of every light of `scene` at `size` × `size` texels per face:
/// casters are the triangles of `raster` that `casters` marks and the exact spheres of `raster`
/// that cast shadows (drawn per texel: their shadows are round). Each face is a depth-only pass
/// of the Z-buffer's tile rasterizer (raster/zbuffer.h), its depths then turned into the map's
/// own (distances from the light, or along a directional light's rays). A directional light's
/// map is fitted to the bounds of the casters alone, so that no map depends on the camera: a
/// session keeps them while the camera moves, and the passes of a supersampled render share
/// them. Tiles render in parallel; the maps do not depend on the thread count.
ShadowMaps build_shadow_maps(const Scene& scene, const RasterScene& raster,
                             const std::vector<uint8_t>& casters, int size,
                             const FaceDepthDrawer* drawer = nullptr);

/// The shadow maps a render of `scene` shades with, its tessellation `raster` (what the camera's
/// vertex stage projects): drawn by build_shadow_maps, or kept. In `cache` (a render session's,
/// core/build_cache.h) each light's map is kept under the light's index and rebuilt only when
/// what it is drawn from changes: the geometry (the cache drops it), the light's position,
/// direction or cone, the map size, or the tessellation of shadow-casting spheres (which follows
/// the camera under flat and Gouraud shading). A change of colour or intensity keeps every map.
/// `shared` (supersampling's passes) keeps the maps of the first pass for the others. `stats`,
/// when given, counts the faces and texels drawn and the maps kept. `drawer`, when given, draws
/// the faces' depth keys (FaceDepthDrawer).
std::shared_ptr<const ShadowMaps> shadow_maps_for_render(
    const Scene& scene, const RasterScene& raster, int size, BuildCache* cache,
    SharedShadowMaps* shared, RenderStats* stats, const FaceDepthDrawer* drawer = nullptr);

/// Whether `p` (a visible point with unit normal `n` on the side the light may reach) is
/// lit according to `map`. The comparison allows a depth bias of one texel plus the slope
/// term texel · tan θ (θ between n and the light), and looks the map up from p moved one
/// texel along n (normal offset): together they keep lit surfaces free of acne, even at
/// grazing light, while contact shadows stay attached (docs/shadows.md).
bool lit_in_shadow_map(const LightShadowMap& map, Vec3 p, Vec3 n);

/// The fraction of `p` lit according to `map`: lit_in_shadow_map's test at a 5 × 5 grid of
/// texels around p, averaged (percentage-closer filtering, Reeves, Salesin & Cook 1987,
/// "Rendering antialiased shadows with depth maps").
float pcf_shadow_fraction(const LightShadowMap& map, Vec3 p, Vec3 n);

/// Percentage-closer soft shadows (Fernando 2005): the mean depth of the casters found around p
/// (blocker search), the penumbra width a light of radius `light_radius` casts from there,
/// w = R (d_receiver − d_blocker) / d_blocker, and percentage-closer filtering over that width
/// (at most k_pcss_max_radius_fraction of the map). Penumbrae widen with the distance between
/// caster and receiver. A directional map or a light of radius 0 gets pcf_shadow_fraction.
float pcss_shadow_fraction(const LightShadowMap& map, Vec3 p, Vec3 n, float light_radius);

/// Whether one of `scene`'s shadow-casting planes lies between `p` and the light seen as `view`
/// (shadow_view): a plane blocks a light at a point when the two are strictly on opposite
/// sides, and a directional light when the ray from `p` toward the light crosses it.
bool plane_blocks_light(const Scene& scene, const LightShadowView& view, Vec3 p);

}  // namespace hikari
