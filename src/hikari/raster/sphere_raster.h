#pragma once
// Spheres drawn exactly by the Z-buffer: the lecture notes that the Z-buffer method works for any
// surface whose depth can be computed at each pixel, not only for polygons. A sphere is a quadric,
// so each pixel's depth is the nearer root of the ray–sphere equation: a conservative screen-space
// bound of the sphere picks the pixels to try, and at each of them the ray the ray tracer casts
// through the pixel centre (scene/camera.h camera_ray) meets the sphere as the ray tracer's
// intersect_sphere (geometry/intersect.h) finds it. Silhouette and hit are then the ray tracer's,
// bit for bit.

#include <cstdint>
#include <span>
#include <vector>

#include "hikari/core/mat4.h"
#include "hikari/core/ray.h"
#include "hikari/frame/tiles.h"
#include "hikari/raster/vertex_pipeline.h"
#include "hikari/scene/camera.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// The ray through the centre of each pixel of a view, unit direction: the camera's own rays
/// (camera_ray at the pixel centre moved by the sample offset, exactly as the ray tracer makes
/// them), or, for a view with no camera (a shadow map's face), the line through the texel centre
/// from the near plane to the far plane of `world_from_clip`.
struct PixelRays {
    bool from_camera = true;
    CameraFrame frame;     ///< from_camera: the camera
    Vec2 sample_offset;    ///< from_camera: RasterView::sample_offset
    Mat4 world_from_clip;  ///< otherwise: the inverse of the view's clip_from_world
    int width = 0, height = 0;

    Ray at(int x, int y) const;
};

/// The rays of the scene camera, sampled at pixel centre + `view.sample_offset`.
PixelRays camera_pixel_rays(const Camera& camera, const RasterView& view);

/// The rays through the texel centres of `view` (its clip_from_world inverted).
PixelRays view_pixel_rays(const RasterView& view);

/// Pixels [x0, x1) × [y0, y1).
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

/// The exact spheres of one view, ready to be drawn tile by tile into a Z-buffer.
///
/// Visibility ids: sphere k of `spheres` is stored in the visibility buffer as `first_id + k`,
/// first_id being the number of screen triangles, so ids below first_id stay ScreenTriangle
/// indices (raster/screen_triangle.h).
struct SphereRaster {
    std::span<const Sphere> spheres;
    PixelRays rays;
    Mat4 clip_from_world;       ///< the view's, for the depth key
    bool orthographic = false;  ///< the view's depth key is 1 / (1.5 − 0.5 z_ndc)
    uint32_t first_id = 0;
    std::vector<PixelRect> bounds;  ///< per sphere: every pixel whose ray can meet it
    /// The spheres whose bound meets each k_tile_size tile of the view (row-major tiles), in
    /// index order, as compressed rows: a tile reads only its own, whatever the sphere count.
    int tiles_x = 0;
    std::vector<uint32_t> tile_begin;
    std::vector<uint32_t> tile_spheres;

    bool is_sphere(uint32_t visible) const {
        return visible >= first_id && visible - first_id < spheres.size();
    }
};

/// Prepares `spheres` for drawing into `view` with visibility ids from `first_id` on. Each
/// sphere's bound is the projection of its world bounding box's corners (a convex hull holding
/// its silhouette) grown by a pixel against rounding; a box reaching across the eye's plane (or
/// not finite) bounds the whole image, one wholly behind it nothing.
SphereRaster prepare_sphere_raster(std::span<const Sphere> spheres, const RasterView& view,
                                   PixelRays rays, uint32_t first_id);

/// The ray of pixel (x, y) in `ray` and where it meets `sphere` as the ray tracer finds it
/// (intersect_sphere's nearer root inside (0, ∞)), NaN when it misses: what the pixel sees
/// where the visibility buffer names that sphere.
float pixel_sphere_hit(const PixelRays& rays, const Sphere& sphere, int x, int y, Ray& ray);

/// The Z-buffer step for spheres at every pixel of `tile`: the nearest sphere the pixel's ray
/// meets replaces what `depth` / `nearest` hold (row-major k_tile_size × k_tile_size, from the
/// tile's corner) when its depth key is strictly smaller, as a later triangle would. The key is
/// the one triangles interpolate: view depth (clip w) under perspective, 1 / (1.5 − 0.5 z_ndc)
/// under a parallel projection. With `fragment_counts` (row-major, `counts_width` wide, the
/// whole image), each sphere a pixel's ray meets adds one fragment to that pixel's count, as a
/// triangle covering it would (`--stats`, the overdraw picture).
void draw_spheres_in_tile(const SphereRaster& raster, const Tile& tile, float* depth,
                          uint32_t* nearest, uint32_t* fragment_counts = nullptr,
                          int counts_width = 0);

}  // namespace hikari
