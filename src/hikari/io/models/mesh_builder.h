#pragma once
// From the polygons a model file describes to the triangle mesh the scene takes: the one place
// where faces are triangulated and missing normals are made, for every format.

#include <filesystem>

#include "hikari/io/models/mesh_data.h"

namespace hikari {

/// How build_mesh() makes what a file leaves out.
struct MeshOptions {
    /// Where a file gives neither normals nor smoothing groups, a corner's normal averages the
    /// faces around its point whose normal is within this angle of its own face's; 0 gives each
    /// face its own normal (flat, the lecture's Fig 4.5), 180 smooths everything. Vertices are
    /// split where normals differ.
    float crease_angle_degrees = 45.0f;
};

/// Triangulates every face of `mesh` (geometry/polygon_triangulation.h: a fan where the polygon
/// is convex, ear clipping where it is not), drops triangles of zero area or with non-finite
/// corners (counted in degenerate_skipped), and fills normals the file does not give: within
/// OBJ smoothing groups when it has them, else by `options.crease_angle_degrees`. Faces that
/// intersect themselves are triangulated as well as can be and named in a warning. Throws
/// InputError "FILE: problem" (with the face's line when known) for a corner index out of range,
/// a face of fewer than 3 corners, or a mesh without one usable triangle.
MeshData build_mesh(const std::filesystem::path& file, PolygonMesh mesh,
                    const MeshOptions& options = {});

/// The bytes build_mesh takes beyond its input for `triangles` triangles over `vertices`
/// vertices: what it checks against --max-memory, and what a loader adds to its own need when
/// the two are held at once.
double mesh_build_bytes(double triangles, double vertices);

}  // namespace hikari
