#pragma once
// The scene as the rasterizer sees it: nothing but triangles. Spheres and planes are tessellated
// (raster/tessellate.h), meshes keep their own triangles.

#include "hikari/scene/scene.h"

namespace hikari {

/// World-space triangles with per-vertex normals, a material and a PrimitiveId per triangle, in
/// scene order (ascending PrimitiveId; a tessellated sphere's or plane's triangles all carry its
/// id). ScreenTriangle::source indexes `triangles`. Fronts wind counter-clockwise, N = (P2 − P1)
/// × (P3 − P2) pointing out of spheres and along a plane's normal.
struct RasterScene {
    TriangleSet triangles;
};

}  // namespace hikari
