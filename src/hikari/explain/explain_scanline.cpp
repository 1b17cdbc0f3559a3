#include <fmt/format.h>

#include "hikari/core/error.h"
#include "hikari/explain/explain.h"
#include "hikari/explain/primitive_names.h"
#include "hikari/raster/scanline.h"

namespace hikari {

std::string explain_scanline_row(const Scene& scene, const RasterSettings& raster, int row) {
    if (row < 0 || row >= scene.camera.height)
        throw InputError(fmt::format("--row {} is outside the {}x{} image (rows 0 to {})", row,
                                     scene.camera.width, scene.camera.height,
                                     scene.camera.height - 1));
    const ProjectedScene ps = project_scene(scene, raster);
    ScanlineRowTrace t;
    scanline_visibility_at(ps.triangles, scene.camera.width, scene.camera.height, row, t);
    const PrimitiveNames names(scene);
    std::string out = fmt::format(
        "Scanline (Alg 4.1) at row {}: the scan line y = {}.5 (pixel centres), image {}x{}\n"
        "Depths are the depth key z = -near/w (smaller is nearer), affine along the line.\n",
        row, row, scene.camera.width, scene.camera.height);
    out += fmt::format("\nEdge table: {} edge(s) start on this row\n", t.starting.size());
    for (const auto& e : t.starting)
        out += fmt::format(
            "  {}: top ({:.3f}, {:.3f}, z {:.6f}), dx/dy {:.4f}, dz/dy {:.6g}, rows {}..{}\n",
            names.screen_triangle(ps, e.triangle), e.x_top, e.y_top, e.z_top, e.dx_dy, e.dz_dy,
            e.first_row, e.last_row);
    out += fmt::format("\nActive edge list at y = {}.5: {} edge(s), by x\n", row, t.active.size());
    for (const auto& a : t.active)
        out += fmt::format("  x = {:10.4f}  z = {:.6f}{}  {}\n", a.x, a.z,
                           view_depth_note(ps.view, a.z), names.screen_triangle(ps, a.triangle));
    out += fmt::format("\nScan segments (a triangle's two active edges): {}\n", t.segments.size());
    for (const auto& g : t.segments)
        out += fmt::format("  {}: x {:.4f} .. {:.4f}, z = {:.6f} {:+.6g}·(x - x_left)\n",
                           names.screen_triangle(ps, g.triangle), g.x_left, g.x_right, g.z_left,
                           g.dz_dx + 0.0);  // + 0.0: no "-0"
    out += fmt::format(
        "\nSample spans (between consecutive segment end points; the nearest segment in each is "
        "visible, split where segments cross in depth): {}\n",
        t.spans.size());
    for (const auto& s : t.spans)
        out += fmt::format("  x {:10.4f} .. {:10.4f}  pixels {}..{}  visible: {}\n", s.x_begin,
                           s.x_end, s.first, s.end - 1, names.screen_triangle(ps, s.triangle));
    if (t.spans.empty()) out += "  none: the whole row shows the background\n";
    return out;
}

}  // namespace hikari
