#include "hikari/raster/wireframe.h"

#include <optional>
#include <utility>
#include <vector>

#include "hikari/core/parallel.h"
#include "hikari/raster/line_projection.h"
#include "hikari/raster/line_raster.h"

namespace hikari {

LineDrawing draw_wireframe(const Scene& scene, const LineSettings& lines) {
    const LineScene ls = prepare_line_scene(scene, lines);
    const TriangleSet& tris = ls.projected.scene.triangles;
    std::vector<std::optional<LineSegment>> projected(ls.edges.size());
    hikari::parallel_for(size_t{0}, ls.edges.size(), [&](size_t k) {
        const ModelEdge& e = ls.edges[k];
        if (!e.own || !edge_has_kept_face(e, ls.back_facing, lines.cull_back_faces)) return;
        projected[k] = project_segment(ls.projected.view, tris.positions[e.v0],
                                       tris.positions[e.v1], lines.width);
        if (!projected[k]) return;
        projected[k]->color = line_color(scene, tris.material[e.faces[0]], lines);
        projected[k]->id = tris.id[e.faces[0]];
    });
    LineDrawing drawing = empty_drawing(scene, lines);
    for (const std::optional<LineSegment>& s : projected)
        if (s) drawing.segments.push_back(*s);
    return drawing;
}

Framebuffer render_wireframe(const Scene& scene, Film film, const RenderSettings& settings,
                             const LineSettings& lines) {
    return rasterize_lines(draw_wireframe(scene, lines), std::move(film), settings.aov_buffers);
}

}  // namespace hikari
