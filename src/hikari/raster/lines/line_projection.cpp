#include "hikari/raster/lines/line_projection.h"

#include <algorithm>

#include "hikari/core/parallel.h"
#include "hikari/raster/cull.h"
#include "hikari/raster/lines/line_clip.h"

namespace hikari {

LineScene prepare_line_scene(const Scene& scene, const LineSettings& lines) {
    RasterSettings raster;
    raster.cull_back_faces = lines.cull_back_faces;
    LineScene ls{project_scene(scene, raster), {}, {}};
    const TriangleSet& tris = ls.projected.scene.triangles;
    ls.back_facing.resize(tris.size());
    hikari::parallel_for(size_t{0}, tris.size(), [&](size_t f) {
        ls.back_facing[f] = is_back_facing(ls.projected.view, tris, f);
    });
    ls.edges = model_edges(tris);
    return ls;
}

bool edge_has_kept_face(const ModelEdge& edge, const std::vector<uint8_t>& back_facing,
                        bool cull_back_faces) {
    if (!cull_back_faces) return true;
    return std::any_of(edge.faces.begin(), edge.faces.end(),
                       [&](uint32_t f) { return f != k_no_face && !back_facing[f]; });
}

Vec3 line_color(const Scene& scene, uint32_t material, const LineSettings& lines) {
    if (lines.color) return *lines.color;
    return material < scene.materials.size() ? scene.materials[material].kd : Vec3(1.0f);
}

LineDrawing empty_drawing(const Scene& scene, const LineSettings& lines) {
    LineDrawing d;
    d.width = scene.camera.width;
    d.height = scene.camera.height;
    d.line_width = lines.width;
    d.camera = make_camera_frame(scene.camera);
    d.background = scene.background;
    return d;
}

std::optional<LineSegment> project_segment(const RasterView& view, Vec3 p, Vec3 q,
                                           float line_width) {
    const Vec4 a = view.clip_from_world * Vec4(p, 1.0f);
    const Vec4 b = view.clip_from_world * Vec4(q, 1.0f);
    // One line width in NDC units (2 units span the image's smaller side at most).
    const float margin = 2.0f * line_width / float(std::min(view.width, view.height));
    const std::optional<ClipInterval> in = clip_segment(a, b, margin);
    if (!in) return std::nullopt;
    LineSegment seg;
    auto end = [&](float t, Vec2& pixel, float& inv_w, Vec3& world) {
        const Vec4 c = a + (b - a) * t;
        inv_w = 1.0f / c.w;
        const Vec3 screen = transform_point(view.screen_from_clip, c.xyz() * inv_w);
        pixel = {screen.x, screen.y};
        world = p + (q - p) * t;
    };
    end(in->t0, seg.a, seg.inv_w_a, seg.world_a);
    end(in->t1, seg.b, seg.inv_w_b, seg.world_b);
    return seg;
}

}  // namespace hikari
