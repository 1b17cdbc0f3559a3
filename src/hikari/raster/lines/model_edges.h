#pragma once
// The edges of a model's faces (the lecture's Fig 4.1a draws them): each edge once, however many
// triangles share it, with the faces on either side, which tell whether it lies on a silhouette
// and which faces cannot hide it.

#include <array>
#include <cstdint>
#include <vector>

#include "hikari/scene/scene.h"

namespace hikari {

/// ModelEdge::faces entry where an edge has no second face (the border of an open surface).
inline constexpr uint32_t k_no_face = UINT32_MAX;

/// An edge of a triangle mesh, shared by the triangles in `faces`.
struct ModelEdge {
    uint32_t v0 = 0, v1 = 0;  ///< vertex indices of its ends (those of its first face)
    std::array<uint32_t, 2> faces{k_no_face, k_no_face};  ///< its first two triangles
    bool own = false;  ///< an edge of the model's own faces (TriangleSet::edge_flags) for some
                       ///< adjacent triangle, not only a triangulation diagonal
};

/// Every edge of `triangles`, each once: two triangle edges are one edge when their ends have
/// the same world positions, compared exactly (vertices are split where normals or texture
/// coordinates differ, positions are not). In a deterministic order. A third or later triangle
/// on one edge (a non-manifold mesh) is not listed in `faces`.
std::vector<ModelEdge> model_edges(const TriangleSet& triangles);

/// Whether the edge's two faces turn different sides to the eye (one front-, one back-facing):
/// the silhouette of the surface, drawn even where it is a triangulation diagonal.
/// `back_facing[f]` is 1 for faces seen from behind.
bool is_silhouette(const ModelEdge& edge, const std::vector<uint8_t>& back_facing);

}  // namespace hikari
