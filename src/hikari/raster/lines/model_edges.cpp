#include "hikari/raster/lines/model_edges.h"

#include <algorithm>
#include <bit>
#include <utility>

#include "hikari/core/huge_page_allocator.h"
#include "hikari/core/parallel.h"
#include "hikari/core/parallel_pages.h"

namespace hikari {

namespace {

/// A position as bits, −0 folded into +0, so that equal positions give equal keys.
std::array<uint32_t, 3> position_bits(Vec3 p) {
    auto bits = [](float v) { return std::bit_cast<uint32_t>(v == 0.0f ? 0.0f : v); };
    return {bits(p.x), bits(p.y), bits(p.z)};
}

/// One triangle edge, keyed by the ranks of its two ends' positions, the smaller first.
struct HalfEdge {
    uint64_t ends;         ///< rank of the smaller end << 32 | rank of the larger
    uint64_t face_corner;  ///< 3 × face + corner: the edge runs from that corner to the next
};

/// Per vertex, the rank of its position among the distinct positions in the order of their bits
/// (x, then y, then z): comparing ranks is comparing the bits, in one integer compare.
std::vector<uint32_t> position_ranks(const std::vector<Vec3>& positions) {
    std::vector<uint32_t> order(positions.size());
    for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    hikari::parallel_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        const auto pa = position_bits(positions[a]), pb = position_bits(positions[b]);
        return pa != pb ? pa < pb : a < b;
    });
    std::vector<uint32_t> rank(positions.size());
    uint32_t r = 0;
    for (size_t k = 0; k < order.size(); ++k) {
        if (k > 0 && position_bits(positions[order[k]]) != position_bits(positions[order[k - 1]]))
            ++r;
        rank[order[k]] = r;
    }
    return rank;
}

}  // namespace

std::vector<ModelEdge> model_edges(const TriangleSet& triangles) {
    const std::vector<uint32_t> rank = position_ranks(triangles.positions);
    // every element written below: no zero pass first, and huge pages where granted
    std::vector<HalfEdge, UninitializedHugePageAllocator<HalfEdge>> half(3 * triangles.size());
    hikari::parallel_for(size_t{0}, triangles.size(), [&](size_t f) {
        for (uint32_t k = 0; k < 3; ++k) {
            uint64_t p = rank[triangles.indices[f][k]];
            uint64_t q = rank[triangles.indices[f][(k + 1) % 3]];
            if (q < p) std::swap(p, q);
            half[3 * f + k] = {p << 32 | q, 3 * uint64_t{f} + k};
        }
    });
    // Sorting by (ends, face, corner) groups the triangle edges of one model edge, in an order
    // that depends on nothing but the mesh (each key is distinct, so on no thread count either).
    hikari::parallel_sort(half.begin(), half.end(), [](const HalfEdge& x, const HalfEdge& y) {
        return x.ends != y.ends ? x.ends < y.ends : x.face_corner < y.face_corner;
    });
    std::vector<ModelEdge> edges;
    edges.reserve(half.size() / 2 + 1);  // a closed mesh's edges; more grow the list
    populate_pages_in_parallel(edges.data(), edges.capacity() * sizeof(ModelEdge));
    for (size_t i = 0; i < half.size();) {
        size_t j = i;
        ModelEdge e;
        const auto face_of = [&](size_t h) {
            return static_cast<uint32_t>(half[h].face_corner / 3);
        };
        const auto corner_of = [&](size_t h) {
            return static_cast<uint32_t>(half[h].face_corner % 3);
        };
        const auto& idx = triangles.indices[face_of(i)];
        e.v0 = idx[corner_of(i)];
        e.v1 = idx[(corner_of(i) + 1) % 3];
        for (; j < half.size() && half[j].ends == half[i].ends; ++j) {
            if (j - i < 2) e.faces[j - i] = face_of(j);
            e.own |= triangles.edge_flags.empty() ||
                     (triangles.edge_flags[face_of(j)] >> corner_of(j)) & 1;
        }
        // a zero-length edge draws nothing
        if ((half[i].ends >> 32) != (half[i].ends & 0xffffffffu)) edges.push_back(e);
        i = j;
    }
    return edges;
}

bool is_silhouette(const ModelEdge& edge, const std::vector<uint8_t>& back_facing) {
    if (edge.faces[1] == k_no_face) return false;
    return back_facing[edge.faces[0]] != back_facing[edge.faces[1]];
}

}  // namespace hikari
