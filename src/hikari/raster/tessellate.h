#pragma once
// Spheres and planes as triangles for the rasterizer (the lecture's pipeline only draws polygons).

#include <cstdint>

#include "hikari/raster/raster_scene.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// Longitude segments of a sphere whose silhouette spans `radius_px` pixels: enough that the
/// polygon's deviation from the circle (its sagitta r (1 − cos π/n)) stays below 0.05 pixel,
/// clamped to [16, 512].
uint32_t sphere_segments(float radius_px);

/// Appends a UV sphere (`lon` segments, `lon / 2` bands, exact vertex normals) to `out`; every
/// triangle carries `material` and `id`.
void tessellate_sphere(const Sphere& sphere, uint32_t lon, TriangleSet& out);

/// Appends a square grid of `half_extent` around the foot of `eye` on the plane: cells grow
/// cubically with distance from the foot, so they are small near the camera and few overall.
void tessellate_plane(const Plane& plane, Vec3 eye, float half_extent, TriangleSet& out);

/// The half extent given to planes: far enough that the gap between the grid's edge and the true
/// horizon is well under a pixel (10^4 times the larger of the eye's height and the scene size).
float plane_half_extent(const Scene& scene);

/// What the rasterizer makes of spheres: polygons (every method), or the spheres themselves for a
/// method that can draw a quadric per pixel (the Z-buffer, raster/sphere_raster.h).
enum class SphereGeometry { tessellated, exact };

/// Every primitive of `scene` as triangles, in scene order. Sphere resolutions follow each
/// sphere's projected size through `scene.camera`; with SphereGeometry::exact the spheres go to
/// RasterScene::spheres instead, except those given a tessellation of their own
/// (Sphere::segments, `--tessellation`): asked for as polygons, they stay polygons.
RasterScene tessellate_scene(const Scene& scene,
                             SphereGeometry spheres = SphereGeometry::tessellated);

/// The triangles tessellate_sphere makes of a sphere of `segments` polygons around its equator.
double sphere_triangle_count(uint32_t segments);

/// Refuses (InputError, core/memory_budget.h) a scene whose tessellation and projection would
/// not fit in the memory limit, before any of it is allocated: what tessellate_scene checks
/// first. The count covers spheres' tessellations (`--tessellation`) and meshes repeated many
/// times alike. Returns the counts it found (at most what tessellate_scene makes).
struct RasterCounts {
    double triangles = 0, vertices = 0;
};
RasterCounts check_raster_memory(const Scene& scene, SphereGeometry spheres);

/// The distance from the camera's eye to the nearest sphere or mesh triangle it could see
/// (RasterScene::nearest_object): triangles wholly behind the eye, and triangles edge-on with
/// the eye in their plane, are left out; a triangle counts by its bounding box (never farther
/// than the triangle). Infinity when there is none.
float nearest_object(const Scene& scene);

}  // namespace hikari
