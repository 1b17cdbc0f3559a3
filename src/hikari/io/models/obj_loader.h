#pragma once
// Wavefront OBJ/MTL meshes (via tinyobjloader), checked and flattened into indexed triangles.

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "hikari/core/vec.h"
#include "hikari/io/models/mesh_builder.h"

namespace hikari {

/// Loads `file` and the MTL libraries it names (relative to the OBJ's directory).
/// Throws InputError "FILE:LINE: problem" (or "FILE: problem" when the line is unknown) for a
/// missing or unreadable file, a malformed or non-finite number, a face with fewer than 3 or
/// more than 255 corners, an index out of range, or a file without a single usable triangle.
MeshData load_obj(const std::filesystem::path& file, const MeshOptions& options = {});

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
