#pragma once
// Stanford PLY meshes (Turk 1994, "The PLY Polygon File Format"): our own compact reader of the
// ascii, binary_little_endian and binary_big_endian 1.0 encodings.

#include <filesystem>
#include <string_view>

#include "hikari/io/models/mesh_builder.h"
#include "hikari/io/models/mesh_data.h"

namespace hikari {

/// Reads the PLY file `bytes` (named `file` in messages) into the polygons it describes: no
/// triangulation, no normals made. From the `vertex` element: x, y, z (required), nx, ny, nz,
/// texture coordinates (s t, u v, texture_u texture_v or texture_s texture_t) and red, green,
/// blue; from `face`: the list `vertex_indices` (or `vertex_index`), faces of any length; from
/// `tristrips`: triangle strips separated by -1, each triangle a face of its own with the strip's
/// orientation. Every other element and property is skipped. Unknown header lines and data after
/// the last element are warnings. Throws InputError "FILE:LINE: problem" (header and ascii body)
/// or "FILE: byte N: problem" (binary body) for anything malformed: a count that is not a whole
/// number or more than the file can hold, a short file, a face of fewer than 3 corners, a corner
/// index out of range, non-finite positions or texture coordinates.
PolygonMesh read_ply(const std::filesystem::path& file, std::string_view bytes);

/// load_model's PLY branch: read_file_bytes + read_ply + build_mesh.
MeshData load_ply(const std::filesystem::path& file, const MeshOptions& options = {});

}  // namespace hikari
