#pragma once
// What the line methods (wireframe, hiddenline) share: the scene's triangles as the raster
// methods tessellate them, their edges, which side each face turns to the eye, and the way an
// edge in world space becomes a LineSegment in pixels.

#include <optional>
#include <vector>

#include "hikari/frame/line_drawing.h"
#include "hikari/raster/lines/line_settings.h"
#include "hikari/raster/lines/model_edges.h"
#include "hikari/raster/vertex_pipeline.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// The scene ready for drawing lines.
struct LineScene {
    ProjectedScene projected;          ///< tessellated, projected, culled as `--cull` says
    std::vector<ModelEdge> edges;      ///< model_edges of projected.scene.triangles
    std::vector<uint8_t> back_facing;  ///< per triangle: 1 where the eye sees its back (Fig 4.3)
};

/// Tessellates and projects `scene` (vertex_pipeline.h, culling when lines.cull_back_faces) and
/// finds the edges and facings of its triangles.
LineScene prepare_line_scene(const Scene& scene, const LineSettings& lines);

/// Whether a face of `edge` survives culling: with culling, faces seen from behind are gone, and
/// an edge with none of its faces left is not drawn.
bool edge_has_kept_face(const ModelEdge& edge, const std::vector<uint8_t>& back_facing,
                        bool cull_back_faces);

/// The colour of lines on faces of material `material`: lines.color, else the material's kd.
Vec3 line_color(const Scene& scene, uint32_t material, const LineSettings& lines);

/// An empty drawing of the camera's size, line width and background.
LineDrawing empty_drawing(const Scene& scene, const LineSettings& lines);

/// The part of world segment (p, q) that `view` sees, clipped in homogeneous clip space
/// (raster/line_clip.h) against the near plane and the frustum's sides (widened by a line
/// width, so that lines along the border keep both halves), mapped to pixels; nullopt when
/// nothing of it is in view.
std::optional<LineSegment> project_segment(const RasterView& view, Vec3 p, Vec3 q,
                                           float line_width);

}  // namespace hikari
