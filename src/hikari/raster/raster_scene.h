#pragma once
// The scene as the rasterizer sees it: nothing but triangles. Spheres and planes are tessellated
// (raster/tessellate.h), meshes keep their own triangles.

#include <vector>

#include "hikari/core/aabb.h"
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
    /// The bounds of every triangle but the planes' (meshes and tessellated spheres).
    Aabb object_bounds;
};

}  // namespace hikari
