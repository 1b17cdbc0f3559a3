#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "hikari/core/error.h"
#include "hikari/explain/explain.h"
#include "hikari/explain/primitive_names.h"
#include "hikari/raster/zbuffer.h"

namespace hikari {

namespace {

std::string depth_text(float z) { return std::isinf(z) ? "∞" : fmt::format("{:.6f}", z); }

}  // namespace

std::string explain_zbuffer_pixel(const Scene& scene, const RasterSettings& raster, int x, int y) {
    if (x < 0 || y < 0 || x >= scene.camera.width || y >= scene.camera.height)
        throw InputError(fmt::format("--pixel {},{} is outside the {}x{} image", x, y,
                                     scene.camera.width, scene.camera.height));
    const ProjectedScene ps = project_scene(scene, raster);
    std::vector<ZBufferFragment> fragments;
    const VisibilityBuffer vis = zbuffer_visibility_at(ps.triangles, scene.camera.width,
                                                       scene.camera.height, x, y, fragments);
    const PrimitiveNames names(scene);
    std::string out = fmt::format(
        "Z-buffer (Alg 4.2) at pixel ({}, {}), centre ({}.5, {}.5)\n"
        "Z(i,j) starts at ∞; each triangle covering the centre gives a fragment of depth\n"
        "z = 1/(1/w interpolated){}; a fragment nearer than Z(i,j) (z < Z) is written.\n"
        "{} of {} projected triangles cover this pixel centre, tested in drawing order:\n",
        x, y, x, y,
        ps.view.orthographic ? " (a parallel view: a monotone key, not a distance)"
                             : " (w: the depth along the view axis)",
        fragments.size(), ps.triangles.size());
    for (size_t k = 0; k < fragments.size(); ++k) {
        const ZBufferFragment& f = fragments[k];
        out += fmt::format("  {:>3}. {}: z = {}, Z(i,j) was {} -> {}\n", k + 1,
                           names.screen_triangle(ps, f.triangle), depth_text(f.depth),
                           depth_text(f.stored),
                           f.won ? "nearer: written, Z(i,j) := z" : "not nearer: discarded");
    }
    const uint32_t seen = vis.triangle[static_cast<size_t>(y) * vis.width + x];
    if (seen == k_no_triangle)
        out += "Result: no fragment; the pixel shows the background.\n";
    else
        out += fmt::format("Result: {} is visible; the shading pass colours the pixel from it.\n",
                           names.screen_triangle(ps, seen));
    return out;
}

}  // namespace hikari
