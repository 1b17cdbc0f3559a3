#pragma once
// What the vertex stage hands to every hidden-surface method: triangles after p_s = V P M p_w,
// clipping and culling, in screen space (the lecture's Fig 4.2, 透視投影 → 隠面消去).

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "hikari/core/vec.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// One vertex after projection.
struct ScreenVertex {
    /// x, y in pixels with (0, 0) the top-left corner of the image (pixel (i, j) has its centre at
    /// (i + 0.5, j + 0.5)); z = −near / w_clip, a depth key in [−1, 0) that is smaller for nearer
    /// points. 1/w is an affine function of (x, y) across a projected triangle (perspective keeps
    /// planes planar), so depth comparisons and plane tests may be done in this space directly;
    /// unlike NDC z, which crowds toward 1 when far/near is large, it keeps full float precision.
    Vec3 position;
    /// 1 / w_clip (= 1 / view-space depth), for perspective-correct interpolation.
    float inv_w = 1;
};

/// A projected triangle. Several may come from one scene triangle (clipping at the near plane
/// splits it); all of them name that source triangle, whose attributes the shading stage reads.
struct ScreenTriangle {
    std::array<ScreenVertex, 3> v;
    uint32_t source = 0;  ///< index into the tessellated scene triangles (RasterScene::triangles)
};

/// Screen triangles given by corner indices into projected vertices (the corners of every triangle
/// of a mesh wholly inside the clip volume: ScreenProjection), built as they are read instead of
/// stored.
struct IndexedScreenTriangles {
    const ScreenVertex* vertices = nullptr;
    const std::array<uint32_t, 3>* indices = nullptr;
    size_t count = 0;

    size_t size() const { return count; }
    ScreenTriangle operator[](size_t t) const {
        const auto& idx = indices[t];
        return {{vertices[idx[0]], vertices[idx[1]], vertices[idx[2]]}, static_cast<uint32_t>(t)};
    }
};

/// Index stored in a visibility buffer where no triangle covers the pixel centre.
inline constexpr uint32_t k_no_triangle = std::numeric_limits<uint32_t>::max();

/// The result of hidden-surface removal: for each pixel centre, the ScreenTriangle seen there.
/// Row-major, row 0 at the top. The Z-buffer may also draw spheres exactly
/// (raster/sphere_raster.h): values from the ScreenTriangle count n on name them, n + k for
/// sphere k of RasterScene::spheres; every reader of a zbuffer's buffer must expect them.
struct VisibilityBuffer {
    int width = 0;
    int height = 0;
    /// index into the ScreenTriangle list, n + sphere index, or k_no_triangle
    std::vector<uint32_t> triangle;
};

}  // namespace hikari
