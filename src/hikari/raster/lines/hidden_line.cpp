#include "hikari/raster/lines/hidden_line.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "hikari/core/cancel.h"
#include "hikari/core/parallel.h"
#include "hikari/raster/lines/line_projection.h"
#include "hikari/raster/lines/line_raster.h"
#include "hikari/raster/screen_grid.h"
#include "hikari/raster/triangle_intersection.h"

namespace hikari {

namespace {

/// Grid cells per projected triangle. The grid covers the part of the projected scene that lines
/// can be drawn in, in about this many cells per triangle, whatever the image size: the work of
/// finding candidates is the same at 1 × 1 as at 1920 × 1080 (the candidates that matter do not
/// depend on the grid, only how many others are looked at).
constexpr double k_cells_per_triangle = 1.0;
/// The most cells of the grid.
constexpr size_t k_max_cells = size_t{1} << 22;
/// Each triangle is binned by its box widened by this fraction of its larger side: the tests
/// below count a point as behind a face up to 1e-4 of the face's size outside it.
constexpr float k_bin_widening = 1e-3f;
/// How far from a line, in cells, the grid looks for its candidates (float noise only: the
/// widened boxes carry the tests' tolerances).
constexpr float k_reach_cells = 0.01f;
/// Relative depth margin: a face hides a point only when nearer by more than this (float noise
/// on a face through the point itself, e.g. a third face on an edge, must not hide it).
constexpr float k_depth_margin = 1e-5f;
/// A point hides behind a face when inside it or on its outline, up to this much outside in
/// barycentric terms: an edge seen exactly behind a nearer edge (both on one line in the image,
/// as opposite edges of a box seen along their diagonal plane) is hidden by the faces there,
/// not drawn twice.
constexpr float k_inside_margin = -1e-5f;
/// Pieces shorter than this many pixels are not classified on their own (see visible_pieces).
constexpr float k_min_piece_pixels = 1e-3f;

/// A projected triangle as a possible occluder: the pixel positions of its corners, its depth
/// key z = −near / w (raster/screen_triangle.h) as an affine function of the pixel position,
/// and its nearest depth.
struct Occluder {
    float x[3], y[3], z[3];  ///< corners: pixel position and depth key
    float area2;             ///< twice the signed area in pixels
    float zx, zy, z0;        ///< z(x, y) = zx·x + zy·y + z0
    float z_min;             ///< nearest depth key of its corners
    Vec2 lo, hi;             ///< its bounding box in pixels
    uint32_t source;         ///< the tessellated triangle it is (part of)
};

/// Whether the boxes [lo, hi] and [a, b] (any order of corners), widened by `margin`, overlap.
bool boxes_overlap(Vec2 lo, Vec2 hi, Vec2 a, Vec2 b, float margin) {
    return std::min(a.x, b.x) - margin <= hi.x && std::max(a.x, b.x) + margin >= lo.x &&
           std::min(a.y, b.y) - margin <= hi.y && std::max(a.y, b.y) + margin >= lo.y;
}

Occluder make_occluder(const ScreenTriangle& t) {
    Occluder o{};
    const float* z = o.z;
    for (int k = 0; k < 3; ++k) {
        o.x[k] = t.v[k].position.x;
        o.y[k] = t.v[k].position.y;
        o.z[k] = t.v[k].position.z;
    }
    const float ex1 = o.x[1] - o.x[0], ey1 = o.y[1] - o.y[0];
    const float ex2 = o.x[2] - o.x[0], ey2 = o.y[2] - o.y[0];
    o.area2 = ex1 * ey2 - ey1 * ex2;
    if (o.area2 != 0.0f) {
        const float dz1 = z[1] - z[0], dz2 = z[2] - z[0];
        o.zx = (dz1 * ey2 - dz2 * ey1) / o.area2;
        o.zy = (dz2 * ex1 - dz1 * ex2) / o.area2;
    }
    o.z0 = z[0] - o.zx * o.x[0] - o.zy * o.y[0];
    o.z_min = std::min({z[0], z[1], z[2]});
    o.lo = {std::min({o.x[0], o.x[1], o.x[2]}), std::min({o.y[0], o.y[1], o.y[2]})};
    o.hi = {std::max({o.x[0], o.x[1], o.x[2]}), std::max({o.y[0], o.y[1], o.y[2]})};
    o.source = t.source;
    return o;
}

/// Barycentric coordinate of (x, y) opposite corner k of `o`.
float barycentric(const Occluder& o, int k, float x, float y) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    return ((o.x[j] - o.x[i]) * (y - o.y[i]) - (o.y[j] - o.y[i]) * (x - o.x[i])) / o.area2;
}

/// Whether (x, y) lies inside `o` by more than `margin` in every barycentric coordinate (a
/// negative margin admits points just outside).
bool inside(const Occluder& o, float x, float y, float margin) {
    return barycentric(o, 0, x, y) > margin && barycentric(o, 1, x, y) > margin &&
           barycentric(o, 2, x, y) > margin;
}

/// A line to test: a segment in pixels with its depth key at both ends, and the (up to two)
/// faces it lies on, which cannot hide it.
struct Line {
    LineSegment seg;
    float za, zb;  ///< depth keys at a and b (affine along the projected segment)
    uint32_t own_faces[2];
};

/// Per-thread scratch of the candidate search: a stamp per occluder marks those already listed.
struct Scratch {
    std::vector<uint32_t> stamp;
    uint32_t epoch = 0;
    std::vector<uint32_t> candidates;
    std::vector<float> splits;
};

Scratch& thread_scratch_for(size_t occluders) {
    thread_local Scratch s;
    if (s.stamp.size() != occluders || ++s.epoch == 0) {
        s.stamp.assign(occluders, 0);
        s.epoch = 1;
    }
    return s;
}

/// What the hidden-line pass reads.
struct Context {
    std::vector<Occluder> occluders;
    ScreenGrid grid;
    Vec2 lo, hi;  ///< the part of the image plane lines can be drawn in (pixels)
};

/// The part of the image plane where a line of `lines.width` can lie (project_segment clips to
/// the view widened by a line width), and a pixel more, cut to the projected triangles' boxes.
void line_domain(const std::vector<ScreenTriangle>& screen, int width, int height, float line_width,
                 Vec2& lo, Vec2& hi) {
    const float side = static_cast<float>(std::max(1, std::min(width, height)));
    const float pad_x = std::abs(line_width) * float(width) / side + 1.0f;
    const float pad_y = std::abs(line_width) * float(height) / side + 1.0f;
    Vec2 t_lo{INFINITY, INFINITY}, t_hi{-INFINITY, -INFINITY};
    for (const ScreenTriangle& t : screen)
        for (const ScreenVertex& v : t.v) {
            t_lo = {std::min(t_lo.x, v.position.x), std::min(t_lo.y, v.position.y)};
            t_hi = {std::max(t_hi.x, v.position.x), std::max(t_hi.y, v.position.y)};
        }
    lo = {std::max(-pad_x, t_lo.x), std::max(-pad_y, t_lo.y)};
    hi = {std::min(float(width) + pad_x, t_hi.x), std::min(float(height) + pad_y, t_hi.y)};
    if (!(lo.x <= hi.x) || !(lo.y <= hi.y)) hi = lo = {0.0f, 0.0f};
}

/// The occluders and their grid over the lines' domain.
Context make_context(const std::vector<ScreenTriangle>& screen, int width, int height,
                     float line_width) {
    Context ctx;
    line_domain(screen, width, height, line_width, ctx.lo, ctx.hi);
    const size_t cells = std::min<size_t>(
        k_max_cells, static_cast<size_t>(k_cells_per_triangle * double(screen.size())) + 1);
    ctx.grid = ScreenGrid(screen, ctx.lo, ctx.hi, cells, k_bin_widening);
    ctx.occluders.resize(screen.size());
    hikari::parallel_for(size_t{0}, screen.size(),
                         [&](size_t i) { ctx.occluders[i] = make_occluder(screen[i]); });
    return ctx;
}

/// The occluders that can hide part of `line`: near enough, not its own faces, listed once.
void find_candidates(const Context& ctx, const Line& line, Scratch& s) {
    s.candidates.clear();
    const float z_far = std::max(line.za, line.zb);
    const float reach = k_reach_cells * ctx.grid.cell_size();
    ctx.grid.for_each_along(line.seg.a, line.seg.b, reach, [&](uint32_t i) {
        if (s.stamp[i] == s.epoch) return;
        s.stamp[i] = s.epoch;
        const Occluder& o = ctx.occluders[i];
        if (o.area2 == 0.0f || o.source == line.own_faces[0] || o.source == line.own_faces[1])
            return;
        if (!(o.z_min < z_far)) return;  // wholly behind the line's farthest point
        if (!boxes_overlap(o.lo, o.hi, line.seg.a, line.seg.b, 0.5f)) return;
        s.candidates.push_back(i);
    });
}

/// Appends the screen parameters s ∈ (0, 1) where `line` may change visibility behind `o`:
/// where its projection crosses o's projected edges, and where it pierces o's plane.
void add_splits(const Occluder& o, const Line& line, std::vector<float>& splits) {
    const float ax = line.seg.a.x, ay = line.seg.a.y;
    const float dx = line.seg.b.x - ax, dy = line.seg.b.y - ay;
    for (int k = 0; k < 3; ++k) {
        const int j = (k + 1) % 3;
        const float ex = o.x[j] - o.x[k], ey = o.y[j] - o.y[k];
        const float denom = dx * ey - dy * ex;
        if (std::abs(denom) <= 1e-12f * (std::abs(dx * ey) + std::abs(dy * ex))) continue;
        const float wx = o.x[k] - ax, wy = o.y[k] - ay;
        const float s = (wx * ey - wy * ex) / denom;
        const float u = (wx * dy - wy * dx) / denom;
        if (!(s > 0.0f && s < 1.0f && u >= -1e-4f && u <= 1.0f + 1e-4f)) continue;
        // Passing the outline of a face that lies behind the line there changes nothing (the
        // face can only come in front where the line pierces its plane, split below).
        const float z = line.za + (line.zb - line.za) * s;
        const float z_face = o.z[k] + u * (o.z[j] - o.z[k]);
        if (z_face < z + k_depth_margin * std::abs(z)) splits.push_back(s);
    }
    // The depth difference line − plane is affine in s: its root is where the line pierces.
    const float g0 = line.za - (o.zx * ax + o.zy * ay + o.z0);
    const float g1 = line.zb - (o.zx * (ax + dx) + o.zy * (ay + dy) + o.z0);
    if ((g0 < 0.0f && g1 > 0.0f) || (g0 > 0.0f && g1 < 0.0f)) {
        const float s = g0 / (g0 - g1);
        if (s > 0.0f && s < 1.0f && inside(o, ax + s * dx, ay + s * dy, -1e-4f))
            splits.push_back(s);
    }
}

/// Whether the point of `line` at s is behind one of the candidate occluders.
bool hidden_at(const Context& ctx, const Line& line, const Scratch& s, float at) {
    const float x = line.seg.a.x + (line.seg.b.x - line.seg.a.x) * at;
    const float y = line.seg.a.y + (line.seg.b.y - line.seg.a.y) * at;
    const float z = line.za + (line.zb - line.za) * at;
    for (const uint32_t i : s.candidates) {
        const Occluder& o = ctx.occluders[i];
        if (!(o.z_min < z)) continue;
        // Barycentric interpolation of the corners' depths: a convex combination, well
        // conditioned even where the plane form z0 + zx x + zy y cancels (far, grazing faces).
        const float b0 = barycentric(o, 0, x, y), b1 = barycentric(o, 1, x, y);
        const float b2 = barycentric(o, 2, x, y);
        if (b0 <= k_inside_margin || b1 <= k_inside_margin || b2 <= k_inside_margin) continue;
        if (b0 * o.z[0] + b1 * o.z[1] + b2 * o.z[2] < z - k_depth_margin * std::abs(z)) return true;
    }
    return false;
}

/// Appel's step for one line: split it where it may pass behind a face, test each piece at its
/// midpoint, and append the visible pieces, consecutive ones merged, to `out`.
void visible_pieces(const Context& ctx, const Line& line, std::vector<LineSegment>& out) {
    Scratch& s = thread_scratch_for(ctx.occluders.size());
    find_candidates(ctx, line, s);
    s.splits.assign({0.0f, 1.0f});
    for (const uint32_t i : s.candidates) add_splits(ctx.occluders[i], line, s.splits);
    std::sort(s.splits.begin(), s.splits.end());
    float run_start = -1.0f;  // start of the visible run being built, −1 while there is none
    const float min_piece = k_min_piece_pixels / std::max(segment_length(line.seg), 1e-30f);
    for (size_t k = 0; k + 1 < s.splits.size(); ++k) {
        const float s0 = s.splits[k], s1 = s.splits[k + 1];
        // A sliver between two splits that (nearly) coincide has its midpoint on a face's
        // outline, where no test can decide: it goes with the piece before it.
        if (!(s1 - s0 > min_piece)) continue;
        const bool visible = !hidden_at(ctx, line, s, 0.5f * (s0 + s1));
        if (visible && run_start < 0.0f) run_start = s0;
        if (!visible && run_start >= 0.0f) {
            out.push_back(sub_segment(line.seg, run_start, s0));
            run_start = -1.0f;
        }
    }
    if (run_start == 0.0f) out.push_back(line.seg);
    if (run_start > 0.0f) out.push_back(sub_segment(line.seg, run_start, 1.0f));
}

/// `segment` as a Line lying on `faces`, with the depth keys the triangles have there.
Line make_line(const LineSegment& segment, const RasterView& view, uint32_t face0, uint32_t face1) {
    return {segment,
            view.depth_key(segment.world_a, segment.inv_w_a),
            view.depth_key(segment.world_b, segment.inv_w_b),
            {face0, face1}};
}

/// The edges a hidden-line drawing tests: model edges and silhouettes with a face left after
/// culling, projected and clipped to the view.
std::vector<Line> edge_lines(const Scene& scene, const LineScene& ls, const LineSettings& lines) {
    const TriangleSet& tris = ls.projected.scene.triangles;
    std::vector<std::optional<Line>> found(ls.edges.size());
    hikari::parallel_for(size_t{0}, ls.edges.size(), [&](size_t k) {
        if (k % 4096 == 0) throw_if_cancelled();  // SIGINT, Ctrl-C in Python
        const ModelEdge& e = ls.edges[k];
        if (!(e.own || is_silhouette(e, ls.back_facing)) ||
            !edge_has_kept_face(e, ls.back_facing, lines.cull_back_faces))
            return;
        std::optional<LineSegment> seg = project_segment(ls.projected.view, tris.positions[e.v0],
                                                         tris.positions[e.v1], lines.width);
        if (!seg) return;
        seg->color = line_color(scene, tris.material[e.faces[0]], lines);
        seg->id = tris.id[e.faces[0]];
        found[k] = make_line(*seg, ls.projected.view, e.faces[0], e.faces[1]);
    });
    std::vector<Line> out;
    for (std::optional<Line>& l : found)
        if (l) out.push_back(*l);
    return out;
}

/// Whether triangles f and g share a corner position (adjacent faces meet, they do not pierce).
bool share_corner(const TriangleSet& tris, uint32_t f, uint32_t g) {
    for (const uint32_t i : tris.indices[f])
        for (const uint32_t j : tris.indices[g])
            if (tris.positions[i] == tris.positions[j]) return true;
    return false;
}

/// The intersection lines of faces that pierce each other (Möller 1997), for the pairs of
/// faces whose projections share a grid cell; each pair once, in face order.
std::vector<Line> intersection_lines(const Scene& scene, const LineScene& ls, const Context& ctx,
                                     const LineSettings& lines) {
    const TriangleSet& tris = ls.projected.scene.triangles;
    const std::vector<ScreenTriangle>& screen = ls.projected.triangles;
    std::vector<std::vector<Line>> found(screen.size());
    hikari::parallel_for(size_t{0}, screen.size(), [&](size_t i) {
        if (i % 1024 == 0) throw_if_cancelled();  // SIGINT, Ctrl-C in Python
        const uint32_t f = screen[i].source;
        if (i > 0 && screen[i - 1].source == f) return;  // the first piece speaks for the face
        Vec2 lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
        for (size_t k = i; k < screen.size() && screen[k].source == f; ++k)
            for (const ScreenVertex& v : screen[k].v) {
                lo = {std::min(lo.x, v.position.x), std::min(lo.y, v.position.y)};
                hi = {std::max(hi.x, v.position.x), std::max(hi.y, v.position.y)};
            }
        // a crossing outside the lines' domain would be clipped away
        if (hi.x < ctx.lo.x || lo.x > ctx.hi.x || hi.y < ctx.lo.y || lo.y > ctx.hi.y) return;
        Scratch& s = thread_scratch_for(ctx.occluders.size());
        s.candidates.clear();
        ctx.grid.for_each_in_box(lo, hi, [&](uint32_t j) {
            if (s.stamp[j] == s.epoch) return;
            s.stamp[j] = s.epoch;
            const Occluder& o = ctx.occluders[j];
            if (o.source > f && boxes_overlap(o.lo, o.hi, lo, hi, 0.0f))
                s.candidates.push_back(o.source);
        });
        std::sort(s.candidates.begin(), s.candidates.end());
        s.candidates.erase(std::unique(s.candidates.begin(), s.candidates.end()),
                           s.candidates.end());
        const Vec3 a[3] = {tris.positions[tris.indices[f][0]], tris.positions[tris.indices[f][1]],
                           tris.positions[tris.indices[f][2]]};
        for (const uint32_t g : s.candidates) {
            const Vec3 b[3] = {tris.positions[tris.indices[g][0]],
                               tris.positions[tris.indices[g][1]],
                               tris.positions[tris.indices[g][2]]};
            Vec3 p, q;
            if (share_corner(tris, f, g) || !triangle_intersection(a, b, p, q)) continue;
            std::optional<LineSegment> seg = project_segment(ls.projected.view, p, q, lines.width);
            if (!seg) continue;
            seg->color = line_color(scene, tris.material[f], lines);
            seg->id = tris.id[f];
            found[i].push_back(make_line(*seg, ls.projected.view, f, g));
        }
    });
    std::vector<Line> out;
    for (std::vector<Line>& v : found) out.insert(out.end(), v.begin(), v.end());
    return out;
}

}  // namespace

LineDrawing draw_hidden_lines(const Scene& scene, const LineSettings& lines) {
    const LineScene ls = prepare_line_scene(scene, lines);
    throw_if_cancelled();  // between the stages, each seconds long on a scanned mesh
    const std::vector<ScreenTriangle>& screen = ls.projected.triangles;
    const Context ctx = make_context(screen, scene.camera.width, scene.camera.height, lines.width);
    throw_if_cancelled();

    std::vector<Line> all = edge_lines(scene, ls, lines);
    throw_if_cancelled();
    std::vector<Line> crossings = intersection_lines(scene, ls, ctx, lines);
    all.insert(all.end(), crossings.begin(), crossings.end());

    std::vector<std::vector<LineSegment>> visible(all.size());
    hikari::parallel_for(size_t{0}, all.size(), [&](size_t k) {
        if (k % 1024 == 0) throw_if_cancelled();  // SIGINT, Ctrl-C
        visible_pieces(ctx, all[k], visible[k]);
    });
    LineDrawing drawing = empty_drawing(scene, lines);
    for (const std::vector<LineSegment>& v : visible)
        drawing.segments.insert(drawing.segments.end(), v.begin(), v.end());
    return drawing;
}

Framebuffer render_hidden_lines(const Scene& scene, Film film, const RenderSettings& settings,
                                const LineSettings& lines) {
    return rasterize_lines(draw_hidden_lines(scene, lines), std::move(film), settings.aov_buffers);
}

}  // namespace hikari
