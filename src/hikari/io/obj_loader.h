#pragma once
// Wavefront OBJ/MTL meshes (via tinyobjloader), checked and flattened into indexed triangles.

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "hikari/core/vec.h"
#include "hikari/scene/material.h"

namespace hikari {

/// An indexed triangle mesh as read from an OBJ file, in the file's own (model) space.
struct MeshData {
    /// One per unique (v, vn, vt) corner combination of the file.
    std::vector<Vec3> positions;
    /// Same size as `positions`, unit length. From the file's `vn` where a corner names a usable
    /// one; otherwise the area-weighted average of the face normals around the position.
    std::vector<Vec3> normals;
    /// Same size as `positions`, or empty when no face corner has a `vt`. (0, 0) for corners
    /// without one in a file that has some.
    std::vector<Vec2> uvs;
    /// Triangles as indices into `positions`, in file face order; a polygon with n corners is
    /// fanned from its first corner into n - 2 triangles. Counter-clockwise is the front:
    /// the face normal is N = (P2 - P1) x (P3 - P2).
    std::vector<std::array<uint32_t, 3>> indices;
    /// Per triangle: an index into `materials`, or -1 when its face has no (known) `usemtl`.
    std::vector<int32_t> material;
    /// Per triangle, bit k set where its edge from corner k to corner (k + 1) % 3 lies on its
    /// polygon's outline (TriangleSet::edge_flags): a fan's diagonals are not the model's edges.
    std::vector<uint8_t> edge_flags;
    /// From the MTL files: Ka, Kd, Ks, Ns, Ni, and d (transparency = 1 - d); reflectivity 0.
    std::vector<Material> materials;
    /// Triangles dropped because they have zero area or non-finite corners. Dropping shifts the
    /// numbering of later triangles.
    size_t degenerate_skipped = 0;
    /// Non-fatal problems (a missing MTL file, an unknown material name), one per entry,
    /// each starting with the file name.
    std::vector<std::string> warnings;
};

/// Loads `file` and the MTL libraries it names (relative to the OBJ's directory).
/// Throws InputError "FILE:LINE: problem" (or "FILE: problem" when the line is unknown) for a
/// missing or unreadable file, a malformed or non-finite number, a face with fewer than 3 or
/// more than 255 corners, an index out of range, or a file without a single usable triangle.
MeshData load_obj(const std::filesystem::path& file);

/// An OBJ file's positions and faces and nothing else, numbered as in the file: what the peer
/// benchmarks read (../bench/SPEC.md §1).
struct ObjTriangles {
    /// Every `v` of the file, in file order, used or not.
    std::vector<Vec3> positions;
    /// The faces' triangles, in file order, as indices into `positions`, triangulated as
    /// tinyobjloader 2.0.0rc10 does it: a triangle as given (degenerate ones too), a quad split
    /// along its shorter diagonal, a larger polygon ear-clipped. (SPEC §1 says "as a fan"; its
    /// meshes hold only triangles.)
    std::vector<std::array<uint32_t, 3>> indices;
};

/// Loads the `v` and `f` statements of `file` as tinyobjloader alone reads them, as the peers do:
/// no MTL library is opened, and numbers are not checked beyond what tinyobjloader does (unlike
/// load_obj). Throws InputError "FILE: problem" for a missing or unreadable file, a statement
/// tinyobjloader cannot parse (its message, which names the line), a file without a triangle,
/// or a triangle referring to a vertex the file does not define (named by its number).
ObjTriangles load_obj_triangles(const std::filesystem::path& file);

}  // namespace hikari
