#pragma once
// Meshes read from model files (OBJ, PLY, glTF): what a loader reads (PolygonMesh), and the
// triangle mesh every loader hands to the scene (MeshData), made by io/mesh_builder.h.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hikari/core/vec.h"
#include "hikari/scene/camera.h"
#include "hikari/scene/light.h"
#include "hikari/scene/material.h"

namespace hikari {

/// The most corners a face may have in any format (OBJ's long-standing limit): ear clipping takes
/// time quadratic in the corners, so a face of 200,000 corners would take minutes.
inline constexpr uint32_t k_max_face_corners = 255;

/// A mesh as a file describes it, before triangulation and normals: vertices with their
/// attributes, and faces as polygons of any number of corners. Every loader fills one and hands
/// it to build_mesh(), so triangulation (ear clipping) and normals (crease angle, smoothing
/// groups) are the same whatever the format.
struct PolygonMesh {
    /// One per vertex of the file (for OBJ: per unique (v, vn, vt) corner). Vertices at exactly
    /// the same position are one point when normals are computed (build_mesh welds them: a
    /// loader need not).
    std::vector<Vec3> positions;
    /// Empty, or one per vertex: the file's normals (not necessarily unit length; a zero or
    /// non-finite one is replaced by a computed normal).
    std::vector<Vec3> normals;
    /// Empty, or one per vertex: texture coordinates, (0, 0) at the bottom left of the image.
    std::vector<Vec2> uvs;
    /// Empty, or one per vertex: linear RGB colours (PLY red/green/blue, sRGB-decoded when 8-bit)
    std::vector<Vec3> colors;
    /// Faces as polygons: face f has the corners corners[face_start[f] .. face_start[f + 1]),
    /// counter-clockwise seen from the front. face_start has one more entry than there are faces.
    std::vector<uint32_t> face_start{0};
    std::vector<uint32_t> corners;
    /// Empty, or per face: an index into `materials`, or -1 for none.
    std::vector<int32_t> face_material;
    /// Empty, or per face: the OBJ smoothing group (`s N`); 0 = `s off` (flat). When some face has
    /// a nonzero group, normals are smoothed within groups instead of by the crease angle.
    std::vector<uint32_t> smoothing_group;
    /// Empty, or per face: the line of the file that gave the face, for messages.
    std::vector<uint32_t> face_line;
    std::vector<Material> materials;
    std::vector<std::string> warnings;

    size_t face_count() const { return face_start.size() - 1; }
    void add_face(std::initializer_list<uint32_t> face_corners) {
        corners.insert(corners.end(), face_corners);
        face_start.push_back(static_cast<uint32_t>(corners.size()));
    }
};

/// A camera a model file names (glTF), in the model's space.
struct ModelCamera {
    std::string name;
    Camera camera;  ///< eye, look_at, up and fov_y_degrees (perspective) from the file
    std::optional<float> aspect;  ///< width / height when the file gives one
};

/// An indexed triangle mesh in the file's own (model) space, as every loader returns it.
struct MeshData {
    /// One per output vertex.
    std::vector<Vec3> positions;
    /// Same size as `positions`, unit length: the file's normals where it gives usable ones,
    /// otherwise computed (io/mesh_builder.h: smoothing groups or the crease angle).
    std::vector<Vec3> normals;
    /// Same size as `positions`, or empty when the file has no texture coordinates.
    std::vector<Vec2> uvs;
    /// Same size as `positions`, or empty when the file has no vertex colours: linear RGB that
    /// multiplies the material's ka and kd (as a texture's colour does).
    std::vector<Vec3> colors;
    /// Triangles as indices into `positions`, in file face order; a polygon of n corners becomes
    /// n - 2 triangles (a fan when convex, ear clipping otherwise). Counter-clockwise is the
    /// front: the face normal is N = (P2 - P1) x (P3 - P2).
    std::vector<std::array<uint32_t, 3>> indices;
    /// Per triangle: an index into `materials`, or -1 when its face has none.
    std::vector<int32_t> material;
    /// Per triangle, bit k set where its edge from corner k to corner (k + 1) % 3 lies on its
    /// polygon's outline (TriangleSet::edge_flags): diagonals are not the model's edges.
    std::vector<uint8_t> edge_flags;
    std::vector<Material> materials;
    /// Triangles dropped because they have zero area or non-finite corners. Dropping shifts the
    /// numbering of later triangles.
    size_t degenerate_skipped = 0;
    /// Non-fatal problems, one per entry, each starting with the file name.
    std::vector<std::string> warnings;
    /// Cameras and lights the file holds (glTF), in model space; used when the model is rendered
    /// as a scene of its own.
    std::vector<ModelCamera> cameras;
    std::vector<Light> lights;
};

}  // namespace hikari
