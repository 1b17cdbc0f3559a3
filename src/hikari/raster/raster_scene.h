#pragma once
// The scene as the rasterizer sees it: triangles. Spheres and planes are tessellated
// (raster/tessellate.h), meshes keep their own triangles; only the Z-buffer may keep spheres
// exact (raster/sphere_raster.h), since it needs nothing but a depth per pixel.

#include <limits>
#include <vector>

#include "hikari/scene/scene.h"

namespace hikari {

/// World-space triangles with per-vertex normals, a material and a PrimitiveId per triangle, in
/// scene order (ascending PrimitiveId; a tessellated sphere's or plane's triangles all carry its
/// id). ScreenTriangle::source indexes `triangles`. Fronts wind counter-clockwise, N = (P2 − P1)
/// × (P3 − P2) pointing out of spheres and along a plane's normal.
struct RasterScene {
    TriangleSet triangles;
    /// The infinite planes tessellated into `triangles`, as the scene gave them: the view setup
    /// finds the nearest of their visible points exactly (make_raster_view).
    std::vector<Plane> planes;
    /// The spheres kept exact rather than tessellated (SphereGeometry::exact), in scene order;
    /// empty when they are in `triangles`.
    std::vector<Sphere> spheres;
    /// The distance from the eye to the nearest mesh triangle or sphere that the view could
    /// show (tessellate_scene: triangles wholly behind the eye, or edge-on with the eye in their
    /// plane, are left out); infinity for none.
    float nearest_object = std::numeric_limits<float>::infinity();
};

}  // namespace hikari
