#include "hikari/raster/lines/wireframe.h"

#include <algorithm>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "hikari/core/cancel.h"
#include "hikari/core/color.h"
#include "hikari/core/parallel.h"
#include "hikari/raster/lines/line_projection.h"
#include "hikari/raster/lines/line_raster.h"

namespace hikari {

LineDrawing draw_wireframe(const Scene& scene, const LineSettings& lines) {
    const LineScene ls = prepare_line_scene(scene, lines);
    const TriangleSet& tris = ls.projected.scene.triangles;
    // Chunks of edges projected in parallel, each into its own list, then joined in edge order
    // into the drawing (sized once): the order does not depend on the thread count.
    constexpr size_t k_chunk = 8192;
    std::vector<std::vector<LineSegment>> chunks((ls.edges.size() + k_chunk - 1) / k_chunk);
    parallel_chunks(ls.edges.size(), k_chunk, [&](size_t c, size_t k0, size_t k1) {
        throw_if_cancelled();  // SIGINT, Ctrl-C in Python: once per chunk
        for (size_t k = k0; k < k1; ++k) {
            const ModelEdge& e = ls.edges[k];
            if (!(e.own || lines.triangle_edges) ||
                !edge_has_kept_face(e, ls.back_facing, lines.cull_back_faces))
                continue;
            std::optional<LineSegment> segment = project_segment(
                ls.projected.view, tris.positions[e.v0], tris.positions[e.v1], lines.width);
            if (!segment) continue;
            segment->color = line_color(scene, tris.material[e.faces[0]], lines);
            segment->id = tris.id[e.faces[0]];
            chunks[c].push_back(*segment);
        }
    });
    std::vector<size_t> offset(chunks.size() + 1, 0);
    for (size_t c = 0; c < chunks.size(); ++c) offset[c + 1] = offset[c] + chunks[c].size();
    LineDrawing drawing = empty_drawing(scene, lines);
    drawing.segments.resize(offset.back());
    hikari::parallel_for(size_t{0}, chunks.size(), [&](size_t c) {
        std::copy(chunks[c].begin(), chunks[c].end(),
                  drawing.segments.begin() + static_cast<std::ptrdiff_t>(offset[c]));
    });
    return drawing;
}

void overlay_wireframe(const Scene& scene, const LineSettings& lines, Vec3 colour,
                       std::span<const float> depth, Image& image) {
    // White lines on black composite to the lines' opacity α in encoded values (each segment
    // does acc += c (1 − acc)); over the picture the same segments give p (1 − α) + colour α.
    LineDrawing drawing = draw_wireframe(scene, lines);
    drawing.background = Vec3(0.0f);
    for (LineSegment& s : drawing.segments) s.color = Vec3(1.0f);
    const Framebuffer alpha =
        rasterize_lines(drawing, Film(image.width, image.height, FilmFormat::linear), false,
                        {depth, k_overlay_depth_tolerance});
    const Image& a = alpha.film.linear();
    const Vec3 line = encode_srgb(colour);
    hikari::parallel_for(size_t{0}, image.pixels.size(), [&](size_t i) {
        const float opacity = linear_to_srgb(a.pixels[i].x);
        if (opacity <= 0.0f) return;
        image.pixels[i] =
            decode_srgb(encode_srgb(image.pixels[i]) * (1.0f - opacity) + line * opacity);
    });
}

Framebuffer render_wireframe(const Scene& scene, Film film, const RenderSettings& settings,
                             const LineSettings& lines) {
    return rasterize_lines(draw_wireframe(scene, lines), std::move(film), settings.aov_buffers);
}

}  // namespace hikari
