#include "hikari/explain/algorithm_aovs.h"

#include <algorithm>

#include <fmt/format.h>

#include "hikari/core/color.h"
#include "hikari/frame/aov_picture.h"
#include "hikari/raster/cull.h"
#include "hikari/raster/depth_sort.h"
#include "hikari/raster/scanline.h"
#include "hikari/raster/tessellate.h"
#include "hikari/raster/vertex_pipeline.h"
#include "hikari/raster/zbuffer.h"

namespace hikari {

namespace {

constexpr Vec3 k_culled_colour{1.0f, 0.0f, 1.0f};  ///< magenta: no shading model gives it

/// Counts per pixel as an image: the ramp (or the numbers, `raw`), background black.
Image count_image(const std::vector<uint32_t>& count, int width, int height, bool raw) {
    Image out(width, height);
    const uint32_t most = count.empty() ? 0 : *std::max_element(count.begin(), count.end());
    for (size_t i = 0; i < count.size(); ++i) {
        if (raw) {
            out.pixels[i] = Vec3(static_cast<float>(count[i]));
        } else if (count[i] > 0) {
            const float t = most > 1 ? static_cast<float>(count[i] - 1) / (most - 1) : 0.0f;
            out.pixels[i] = decode_srgb(ramp_colour(t));
        }
    }
    return out;
}

std::string overdraw_summary(const std::vector<uint32_t>& count, std::string_view what) {
    uint64_t total = 0, covered = 0;
    uint32_t most = 0;
    for (const uint32_t c : count) total += c, covered += c > 0, most = std::max(most, c);
    return fmt::format(
        "overdraw: {} {} in all, {:.2f} per covered pixel, at most {} at one "
        "pixel (ramp: dark blue 1 to white {})",
        total, what, covered ? double(total) / double(covered) : 0.0, most, most);
}

/// The Z-buffer's overdraw: fragments depth-tested per pixel.
AlgorithmAov zbuffer_overdraw(const ProjectedScene& ps, int width, int height, bool raw) {
    std::vector<uint32_t> count;
    zbuffer_visibility_counted(ps.triangles, width, height, count);
    return {count_image(count, width, height, raw),
            overdraw_summary(count, "fragments depth-tested")};
}

/// The depth sort's overdraw: polygons painted per pixel.
AlgorithmAov depth_sort_overdraw(const DepthSortTrace& trace, int width, int height, bool raw) {
    return {count_image(trace.paint_count, width, height, raw),
            overdraw_summary(trace.paint_count, "polygon paints")};
}

AlgorithmAov paint_order(const DepthSortTrace& trace, int width, int height, bool raw) {
    Image out(width, height);
    const size_t n = trace.painted.size();
    size_t pieces_seen = 0;
    for (size_t i = 0; i < trace.visible_paint.size(); ++i) {
        const uint32_t k = trace.visible_paint[i];
        if (k == UINT32_MAX) continue;
        if (raw) {
            out.pixels[i] = Vec3(static_cast<float>(k + 1));
            continue;
        }
        Vec3 c = ramp_colour(n > 1 ? static_cast<float>(k) / static_cast<float>(n - 1) : 0.0f);
        // Pieces of split polygons: darker diagonal stripes.
        const bool piece = trace.painted[k] >= trace.sorted.size();
        const int x = static_cast<int>(i % width), y = static_cast<int>(i / width);
        if (piece && (x + y) % 6 < 2) c *= 0.45f;
        pieces_seen += piece;
        out.pixels[i] = decode_srgb(c);
    }
    size_t splits = 0;
    for (const DepthSortTrace::Step& s : trace.steps)
        splits += s.kind == DepthSortTrace::Kind::split;
    return {std::move(out),
            fmt::format("paint-order: {} polygons painted back to front (ramp: dark blue first, "
                        "white last), {} splits; {} pixels show a piece of a split polygon "
                        "(striped)",
                        n, splits, pieces_seen)};
}

AlgorithmAov spans(const Scene& scene, const MethodSettings& own) {
    const int width = scene.camera.width, height = scene.camera.height;
    const ProjectedScene ps = project_scene(scene, own.raster);
    std::vector<uint8_t> starts;
    const VisibilityBuffer vis = scanline_visibility_spans(ps.triangles, width, height, starts);
    Image out(width, height);
    size_t count = 0;
    for (size_t i = 0; i < starts.size(); ++i) {
        count += starts[i];
        if (starts[i])
            out.pixels[i] = Vec3(1.0f);
        else if (vis.triangle[i] != k_no_triangle)
            out.pixels[i] = decode_srgb(0.4f * index_colour(vis.triangle[i]));
    }
    return {std::move(out),
            fmt::format("spans: {} sample spans (white: each span's first pixel; colours: the "
                        "visible triangle)",
                        count)};
}

AlgorithmAov culled(const Scene& scene, const Method& method, const MethodSettings& own) {
    RenderSettings settings;
    settings.aov_buffers = false;
    Framebuffer fb =
        render_scene(method, scene, Film(scene.camera, FilmFormat::linear), settings, own);
    Image out = aov_image(std::move(fb), Aov::color);
    // Every triangle, culled or not, through the Z-buffer: where a back face (D = V·N > 0) is
    // the nearest, culling changes the picture (an open mesh's inside, a face wound the wrong
    // way); on a closed mesh every back face lies behind a front face and culling only saves
    // work.
    const RasterScene rs = tessellate_scene(scene);
    const RasterView view = make_raster_view(scene.camera, rs, own.raster.sample_offset);
    const ProjectedScene all = project_triangles(rs, view, false);
    const TriangleSet& tris = all.scene.triangles;
    std::vector<uint8_t> is_back(tris.size(), 0);
    size_t back_faces = 0;
    for (size_t t = 0; t < tris.size(); ++t) {
        is_back[t] = is_back_facing(view, tris, t);
        back_faces += is_back[t];
    }
    const VisibilityBuffer vis = zbuffer_visibility(all.triangles, out.width, out.height);
    size_t shown = 0;
    for (size_t i = 0; i < vis.triangle.size(); ++i) {
        const uint32_t t = vis.triangle[i];
        if (t == k_no_triangle || !is_back[all.triangles[t].source]) continue;
        out.pixels[i] = 0.4f * out.pixels[i] + 0.6f * k_culled_colour;
        ++shown;
    }
    return {std::move(out),
            fmt::format("culled: {} of {} triangles are back faces (D = V·N > 0), which --cull "
                        "back drops; at {} pixels one would be the nearest surface (magenta)",
                        back_faces, tris.size(), shown)};
}

}  // namespace

AlgorithmAov algorithm_aov(const Scene& scene, const Method& method, Aov aov,
                           const MethodSettings& own, bool raw) {
    return method.algorithm_aovs.draw(scene, method, aov, own, raw);
}

AlgorithmAov zbuffer_algorithm_aov(const Scene& scene, const Method& method, Aov aov,
                                   const MethodSettings& own, bool raw) {
    if (aov == Aov::culled) return culled(scene, method, own);
    return zbuffer_overdraw(project_scene(scene, own.raster), scene.camera.width,
                            scene.camera.height, raw);
}

AlgorithmAov scanline_algorithm_aov(const Scene& scene, const Method& method, Aov aov,
                                    const MethodSettings& own, bool) {
    if (aov == Aov::culled) return culled(scene, method, own);
    return spans(scene, own);
}

AlgorithmAov depth_sort_algorithm_aov(const Scene& scene, const Method& method, Aov aov,
                                      const MethodSettings& own, bool raw) {
    if (aov == Aov::culled) return culled(scene, method, own);
    const int width = scene.camera.width, height = scene.camera.height;
    const ProjectedScene ps = project_scene(scene, own.raster);
    DepthSortTrace trace;
    depth_sort_visibility_traced(ps.triangles, width, height, trace);
    if (aov == Aov::paint_order) return paint_order(trace, width, height, raw);
    return depth_sort_overdraw(trace, width, height, raw);
}

}  // namespace hikari
