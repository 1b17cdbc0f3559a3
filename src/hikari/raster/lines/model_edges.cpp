#include "hikari/raster/lines/model_edges.h"

#include <algorithm>
#include <bit>
#include <tuple>

namespace hikari {

namespace {

/// A position as bits, −0 folded into +0, so that equal positions give equal keys.
std::array<uint32_t, 3> position_bits(Vec3 p) {
    auto bits = [](float v) { return std::bit_cast<uint32_t>(v == 0.0f ? 0.0f : v); };
    return {bits(p.x), bits(p.y), bits(p.z)};
}

/// One triangle edge, keyed by its two ends' positions, the smaller first.
struct HalfEdge {
    std::array<uint32_t, 3> lo, hi;
    uint32_t face;
    uint8_t corner;  ///< the edge runs from corner `corner` to (corner + 1) % 3
};

}  // namespace

std::vector<ModelEdge> model_edges(const TriangleSet& triangles) {
    std::vector<HalfEdge> half(3 * triangles.size());
    for (uint32_t f = 0; f < triangles.size(); ++f)
        for (uint8_t k = 0; k < 3; ++k) {
            auto p = position_bits(triangles.positions[triangles.indices[f][k]]);
            auto q = position_bits(triangles.positions[triangles.indices[f][(k + 1) % 3]]);
            if (q < p) std::swap(p, q);
            half[3 * f + k] = {p, q, f, k};
        }
    // Sorting by (ends, face, corner) groups the triangle edges of one model edge, in an order
    // that depends on nothing but the mesh.
    std::sort(half.begin(), half.end(), [](const HalfEdge& x, const HalfEdge& y) {
        return std::tie(x.lo, x.hi, x.face, x.corner) < std::tie(y.lo, y.hi, y.face, y.corner);
    });
    std::vector<ModelEdge> edges;
    for (size_t i = 0; i < half.size();) {
        size_t j = i;
        ModelEdge e;
        const auto& idx = triangles.indices[half[i].face];
        e.v0 = idx[half[i].corner];
        e.v1 = idx[(half[i].corner + 1) % 3];
        for (; j < half.size() && half[j].lo == half[i].lo && half[j].hi == half[i].hi; ++j) {
            const HalfEdge& h = half[j];
            if (j - i < 2) e.faces[j - i] = h.face;
            e.own |= triangles.edge_flags.empty() || (triangles.edge_flags[h.face] >> h.corner) & 1;
        }
        if (half[i].lo != half[i].hi) edges.push_back(e);  // a zero-length edge draws nothing
        i = j;
    }
    return edges;
}

bool is_silhouette(const ModelEdge& edge, const std::vector<uint8_t>& back_facing) {
    if (edge.faces[1] == k_no_face) return false;
    return back_facing[edge.faces[0]] != back_facing[edge.faces[1]];
}

}  // namespace hikari
