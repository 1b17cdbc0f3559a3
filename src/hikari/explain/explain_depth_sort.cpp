#include <fmt/format.h>

#include "hikari/explain/explain.h"
#include "hikari/explain/primitive_names.h"
#include "hikari/raster/depth_sort.h"

namespace hikari {

namespace {

using Settled = DepthSortTrace::Settled;
using Kind = DepthSortTrace::Kind;

std::string_view settled_text(Settled s) {
    switch (s) {
        case Settled::x_extents:
            return "test 1: x extents apart -> P may go first";
        case Settled::y_extents:
            return "test 2: y extents apart -> P may go first";
        case Settled::p_behind_q:
            return "test 3: P wholly behind Q's plane -> P may go first";
        case Settled::q_in_front:
            return "test 4: Q wholly in front of P's plane -> P may go first";
        case Settled::no_overlap:
            return "test 5: projections do not overlap -> P may go first";
        case Settled::q_may_hide:
            return "all five fail: Q may hide part of P";
    }
    return "";
}

std::string_view cut_text(DepthSortTrace::Cut c) {
    switch (c) {
        case DepthSortTrace::Cut::by_plane:
            return "by the plane of";
        case DepthSortTrace::Cut::by_edge_line:
            return "along an edge line of";
        case DepthSortTrace::Cut::halved:
            return "in half (a cycle no plane cuts) beside";
    }
    return "";
}

}  // namespace

std::string explain_depth_sort(const Scene& scene, const RasterSettings& raster, size_t max_steps) {
    const ProjectedScene ps = project_scene(scene, raster);
    DepthSortTrace t;
    depth_sort_visibility_traced(ps.triangles, scene.camera.width, scene.camera.height, t);
    const PrimitiveNames names(scene);
    auto polygon = [&](uint32_t id) {
        return fmt::format("P{} ({}{})", id, names.screen_triangle(ps, t.source[id]),
                           id < t.sorted.size() ? "" : ", a piece");
    };
    std::string out = fmt::format(
        "Depth sort (Newell, Newell & Sancha 1972; Fig 4.6-4.9), image {}x{}\n"
        "Polygons P0..P{} are the projected triangles; pieces of splits are numbered after them.\n"
        "Depth is the key z = -near/w (larger is farther).\n\n"
        "1. The list by farthest depth (Fig 4.6), farthest first:\n",
        scene.camera.width, scene.camera.height, t.sorted.empty() ? 0 : t.sorted.size() - 1);
    // Every list is cut after max_steps lines: a scanned mesh has millions of polygons, and the
    // view is for following the algorithm, not for reading them all (the counts are of all).
    for (size_t k = 0; k < t.sorted.size() && k < max_steps; ++k)
        out += fmt::format("  {}\n", polygon(t.sorted[k]));
    if (t.sorted.size() > max_steps)
        out += fmt::format("  ... {} more polygons not shown\n", t.sorted.size() - max_steps);
    out +=
        "\n2. For the polygon P at the far end, each Q whose depth range overlaps P's is "
        "compared (Newell's tests 1-5);\n   if Q may hide P, Q moves ahead (reorder) unless it "
        "already waits ahead (a cycle, Fig 4.9a) or they interpenetrate (Fig 4.9b): then a "
        "split.\n";
    size_t shown = 0, splits = 0, reorders = 0;
    for (const DepthSortTrace::Step& s : t.steps) {
        splits += s.kind == Kind::split;
        reorders += s.kind == Kind::reorder;
        if (shown++ >= max_steps) continue;
        switch (s.kind) {
            case Kind::compare:
                out += fmt::format("  compare P{} with Q = P{}: {}\n", s.p, s.q,
                                   settled_text(s.settled));
                break;
            case Kind::reorder:
                out +=
                    fmt::format("  reorder: P{} goes ahead of P{} (painted before it)\n", s.q, s.p);
                break;
            case Kind::split:
                out += fmt::format("  split {} {} P{} -> {} piece(s)\n", polygon(s.p),
                                   cut_text(s.cut), s.q, s.pieces);
                break;
            case Kind::paint:
                out += fmt::format("  paint P{}\n", s.p);
                break;
        }
    }
    if (shown > max_steps) out += fmt::format("  ... {} more steps not shown\n", shown - max_steps);
    out += fmt::format(
        "\n3. Painting order, back to front ({} polygons, {} reorderings, {} "
        "splits):\n",
        t.painted.size(), reorders, splits);
    for (size_t k = 0; k < t.painted.size() && k < max_steps; ++k)
        out += fmt::format("  {:>4}. {}\n", k + 1, polygon(t.painted[k]));
    if (t.painted.size() > max_steps)
        out += fmt::format("  ... {} more polygons not shown\n", t.painted.size() - max_steps);
    return out;
}

}  // namespace hikari
