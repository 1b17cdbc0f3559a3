#pragma once
// The depth sort (奥行きソート法, the lecture's Fig 4.6-4.9): painter's algorithms that paint
// polygons back to front, later paints covering earlier ones.

#include <cstdint>
#include <span>
#include <vector>

#include "hikari/core/mat4.h"
#include "hikari/frame/film.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/frame/render_settings.h"
#include "hikari/raster/raster_settings.h"
#include "hikari/raster/screen_triangle.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// Visible triangle at every pixel centre by the depth sort done properly (Newell, Newell & Sancha
/// 1972): sort by farthest depth, order overlapping pairs by the extent, plane-side and projection
/// tests, and split polygons by each other's planes where the order is cyclic (Fig 4.9a) or they
/// interpenetrate (Fig 4.9b); then paint back to front. Every piece keeps its ScreenTriangle index.
/// Coverage follows the top-left rule at pixel centres (raster/polygon_fill.h); zero-area and
/// non-finite triangles are ignored; nothing is culled. Deterministic.
VisibilityBuffer depth_sort_visibility(std::span<const ScreenTriangle> triangles, int width,
                                       int height);

/// What a depth sort cost (`--stats`).
struct DepthSortCounts {
    uint64_t splits = 0;    ///< polygons cut
    uint64_t paints = 0;    ///< pixels painted, every overwrite counted
    uint64_t polygons = 0;  ///< in the painting order (each piece of a split polygon one)
    /// The polygons pierce one another so much that cutting them all would take cuts quadratic
    /// in their number: the sort stopped cutting and painted the order it had (some pixels may
    /// show a farther polygon).
    bool gave_up = false;
};

/// depth_sort_visibility, also counting into `counts`, painting only the first `paint_limit`
/// polygons of the order (Fig 4.6 part-way; `counts.polygons` still counts them all).
VisibilityBuffer depth_sort_visibility_counted(std::span<const ScreenTriangle> triangles, int width,
                                               int height, DepthSortCounts& counts,
                                               uint32_t paint_limit = UINT32_MAX);

/// What the depth sort did, step by step (`hikari explain -m depthsort`, `--aov paint-order`).
/// Polygons are numbered in creation order: the scene's triangles first (those that cover any
/// area), then each split's pieces.
struct DepthSortTrace {
    /// Newell's tests that can settle a pair (P, Q) as "P may be painted before Q".
    enum class Settled : uint8_t {
        x_extents = 1,   ///< test 1: the x extents do not overlap
        y_extents = 2,   ///< test 2: the y extents do not overlap
        p_behind_q = 3,  ///< test 3: P lies wholly behind Q's plane
        q_in_front = 4,  ///< test 4: Q lies wholly in front of P's plane
        no_overlap = 5,  ///< test 5: the projections do not overlap
        q_may_hide = 0,  ///< none: Q may hide part of P
    };
    enum class Kind : uint8_t {
        compare,  ///< P was compared with Q; `settled` says how
        reorder,  ///< Q moved ahead of P (painted before it)
        split,    ///< polygon `p` was cut by the plane of `q` (or its edge line, or halved)
        paint,    ///< polygon `p` painted
    };
    enum class Cut : uint8_t { by_plane, by_edge_line, halved };
    struct Step {
        Kind kind = Kind::compare;
        uint32_t p = 0, q = 0;
        Settled settled = Settled::q_may_hide;
        Cut cut = Cut::by_plane;
        uint32_t pieces = 0;  ///< split: how many pieces kept (0 to 2)
    };
    std::vector<uint32_t> source;   ///< per polygon: the ScreenTriangle it is (a piece of)
    std::vector<uint32_t> sorted;   ///< the first list, by farthest depth (Fig 4.6)
    std::vector<Step> steps;        ///< every step, in order
    std::vector<uint32_t> painted;  ///< polygons in painting order, back to front
    /// Per pixel: the position in `painted` of the polygon that painted it last (the visible
    /// one), or UINT32_MAX where none did; and how many polygons painted it.
    std::vector<uint32_t> visible_paint;
    std::vector<uint32_t> paint_count;
};

/// depth_sort_visibility, recording every step into `trace`.
VisibilityBuffer depth_sort_visibility_traced(std::span<const ScreenTriangle> triangles, int width,
                                              int height, DepthSortTrace& trace);

/// The naive depth sort of Fig 4.7: order whole polygons by the depth of their centroids and
/// paint back to front, with no overlap tests and no splitting. Wrong wherever that order is
/// (Fig 4.7, cyclic overlap Fig 4.9a, interpenetration Fig 4.9b, a concave polygon Fig 4.9c);
/// kept to show those failures. `polygon_depth[s]`, indexed by ScreenTriangle::source, is the
/// eye-space depth of the centroid of the polygon that source triangle belongs to
/// (polygon_centroid_depths); empty: each triangle is its own polygon, keyed by the mean of its
/// corners' screen z.
VisibilityBuffer depth_sort_naive_visibility(std::span<const ScreenTriangle> triangles, int width,
                                             int height,
                                             std::span<const double> polygon_depth = {});

/// Per triangle of `scene`, the eye-space depth (distance along the view direction, from
/// view_from_world) of the centroid (重心, area-weighted) of the polygon it belongs to: the
/// triangles of one model face, joined across the diagonals its triangulation added (edges
/// without TriangleSet::edge_flags), are one polygon, as the lecture's painter sorts them.
std::vector<double> polygon_centroid_depths(const TriangleSet& triangles,
                                            const Mat4& view_from_world);

/// The `depthsort` method: vertex stage, depth_sort_visibility, shared shading pass.
Framebuffer render_depth_sort(const Scene& scene, Film film, const RenderSettings& settings = {},
                              const RasterSettings& raster = {});

/// The `depthsort-naive` method: vertex stage, depth_sort_naive_visibility, shared shading pass.
Framebuffer render_depth_sort_naive(const Scene& scene, Film film,
                                    const RenderSettings& settings = {},
                                    const RasterSettings& raster = {});

}  // namespace hikari
