#pragma once
// Shadow volumes (Crow 1977, "Shadow algorithms for computer graphics"): the region a caster
// hides from a light is bounded by polygons — the caster's faces toward the light, its
// silhouette edges extruded away from the light to infinity, and a cap at infinity — and a
// visible point is in shadow when it lies inside that region. Inside is decided per pixel by
// counting boundary crossings in a stencil buffer (Heidmann 1991), with the z-fail rule
// (Carmack 2000; Everitt & Kilgard 2002) that stays right when the camera stands inside a
// volume or the near plane cuts one.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "hikari/core/vec.h"
#include "hikari/raster/vertex_pipeline.h"
#include "hikari/scene/camera.h"
#include "hikari/scene/light.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// One boundary polygon of a shadow volume: 3 or 4 corners in homogeneous world coordinates
/// (w = 1 for points, w = 0 for points at infinity), wound counter-clockwise seen from outside
/// the volume.
struct VolumePolygon {
    std::array<Vec4, 4> v;
    int count = 3;
};

/// The boundary polygons of the shadow volumes that the triangles of `tris` marked in
/// `casters` cast in `light`. A closed part of the mesh (every edge shared by exactly two of
/// its triangles, wound oppositely) gets one volume: its light-facing triangles as the front
/// cap, its silhouette edges (between a triangle facing the light and one facing away)
/// extruded to infinity, and the front cap projected to infinity, reversed, as the back cap.
/// Anything else (open meshes, single triangles) gets one volume per triangle, which is right
/// for any input but larger. Vertices are welded by exact position to find shared edges.
std::vector<VolumePolygon> shadow_volume_polygons(const TriangleSet& tris,
                                                  const std::vector<uint8_t>& casters,
                                                  const Light& light);

/// Per pixel of a width × height image, 1 where the visible point — at eye distance
/// `depth[pixel]` along the camera ray through the pixel centre, infinity where nothing is
/// seen — lies inside the volumes bounded by `polygons`, else 0. The stencil count, z-fail:
/// every polygon fragment not in front of the visible point adds +1 where the camera sees the
/// polygon's inside (its back) and −1 where it sees its outside; a nonzero count means shadow.
/// Polygons are projected through `view`, clipped at the near plane like every triangle and
/// rasterized under the top-left rule, so shared edges are counted once; a fragment's depth is
/// exact: the camera ray meets the polygon's plane. Parallel over tiles.
std::vector<uint8_t> stencil_shadow_mask(std::span<const VolumePolygon> polygons,
                                         const RasterView& view, const CameraFrame& frame,
                                         std::span<const float> depth);

}  // namespace hikari
