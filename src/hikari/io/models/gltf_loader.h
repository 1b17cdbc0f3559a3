#pragma once
// glTF 2.0 models (.gltf with its buffers and images, or binary .glb) through tinygltf: the
// default scene's meshes flattened into world space, with its materials, cameras and
// KHR_lights_punctual lights. docs/scene-format.md, "glTF models", states every mapping.

#include <filesystem>
#include <vector>

#include "hikari/io/models/mesh_builder.h"

namespace hikari {

/// What a glTF file holds, before triangulation and normals are made (io/mesh_builder.h).
struct GltfContent {
    /// Every triangle of the scene's mesh primitives, in world space (the node transforms applied),
    /// as 3-corner faces counter-clockwise from the front, with face_material per face. Normals
    /// are set for every vertex when some primitive has them: (0, 0, 0) for the vertices of
    /// primitives without, which build_mesh() replaces by computed ones.
    PolygonMesh mesh;
    /// The perspective cameras the scene's nodes instance, in world space.
    std::vector<ModelCamera> cameras;
    /// The KHR_lights_punctual point and directional lights the scene's nodes instance.
    std::vector<Light> lights;
};

/// Reads `file` (.glb when it starts with the GLB magic "glTF", else glTF JSON) and the buffers
/// and images it refers to (relative to its directory, through read_file_bytes). Walks the default
/// scene (else scene 0, else every root node). Throws InputError "FILE: problem", naming the
/// mesh, primitive, accessor or node, for malformed JSON or GLB, a missing or short buffer file
/// (named), an index or byte range out of bounds, an unsupported required extension or accessor
/// (sparse), or an unusable texture image.
GltfContent read_gltf(const std::filesystem::path& file);

/// load_model's glTF branch (.gltf with its .bin and images, or binary .glb): read_gltf(), then
/// build_mesh(), with the file's cameras and lights in MeshData::cameras and MeshData::lights.
MeshData load_gltf(const std::filesystem::path& file, const MeshOptions& options = {});

}  // namespace hikari
