#pragma once
// What each fuzz target does with one input, shared by the libFuzzer targets in fuzz/ and by
// tests/io/fuzz_regression_test.cpp, which replays every input that once broke hikari.
// Each function returns normally when the input loads or is refused with InputError; anything
// else (a crash, a sanitizer report, an inconsistent result: std::abort) is a bug.

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "hikari/core/error.h"
#include "hikari/io/images/image_read.h"
#include "hikari/io/models/gltf_loader.h"
#include "hikari/io/models/material_rules.h"
#include "hikari/io/models/mtl_scan.h"
#include "hikari/io/models/obj_loader.h"
#include "hikari/io/models/ply_loader.h"
#include "hikari/io/scene/scene_json.h"

namespace hikari::fuzz {

/// Writes `data` to a file named `name` in this process's private temporary directory: the
/// loaders read by path (to resolve MTL files and to name the file in errors).
inline std::filesystem::path write_input(const uint8_t* data, size_t size,
                                         const std::string& name) {
    static const std::filesystem::path dir = [] {
        auto d =
            std::filesystem::temp_directory_path() / ("hikari-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    const auto path = dir / name;
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    return path;
}

/// Scene JSON text -> Scene.
inline void scene_json_input(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    std::vector<std::string> warnings;
    try {
        // Mesh paths resolve under a directory that does not exist: fuzzing must not read the
        // machine's files.
        parse_scene(text, "fuzz.json", "/nonexistent-hikari-fuzz", warnings);
    } catch (const InputError&) {
    }
}

/// Aborts unless a loaded mesh is internally consistent: a normal (and uv, if any) per position,
/// a material per triangle that is one of the mesh's or none, every corner a vertex.
inline void check_mesh(const MeshData& mesh) {
    if (mesh.normals.size() != mesh.positions.size() ||
        mesh.material.size() != mesh.indices.size() ||
        (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size()))
        std::abort();
    for (const auto& triangle : mesh.indices)
        for (uint32_t i : triangle)
            if (i >= mesh.positions.size()) std::abort();
    for (int32_t m : mesh.material)
        if (m < -1 || m >= static_cast<int32_t>(mesh.materials.size())) std::abort();
}

/// OBJ text -> MeshData, which must be internally consistent.
inline void obj_input(const uint8_t* data, size_t size) {
    try {
        const MeshData mesh = load_obj(write_input(data, size, "input.obj"));
        check_mesh(mesh);
    } catch (const InputError&) {
    }
}

/// MTL text: our scan alone (in memory), then as the library of a one-triangle OBJ that uses its
/// first material, through tinyobjloader and the material rule; every material that loads must
/// pass that rule.
inline void mtl_input(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        scan_mtl_text("input.mtl", text);
    } catch (const InputError&) {
    }
    const auto mtl = write_input(data, size, "input.mtl");
    const std::string obj = "mtllib input.mtl\nusemtl a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    try {
        const MeshData mesh = load_obj(write_input(reinterpret_cast<const uint8_t*>(obj.data()),
                                                   obj.size(), "input-with-mtl.obj"));
        for (const Material& m : mesh.materials)
            if (find_material_problem(m)) std::abort();
        check_mesh(mesh);
    } catch (const InputError&) {
    }
}

/// PLY bytes -> PolygonMesh (read_ply) -> MeshData (build_mesh, as load_ply does), each of which
/// must be internally consistent. The bytes are read in memory: load_ply adds only the file read.
inline void ply_input(const uint8_t* data, size_t size) {
    try {
        const std::string_view bytes(reinterpret_cast<const char*>(data), size);
        PolygonMesh polygons = read_ply("input.ply", bytes);
        const size_t vertices = polygons.positions.size();
        for (size_t attribute :
             {polygons.normals.size(), polygons.uvs.size(), polygons.colors.size()})
            if (attribute != 0 && attribute != vertices) std::abort();
        if (polygons.face_start.empty() || polygons.face_start.front() != 0 ||
            polygons.face_start.back() != polygons.corners.size() ||
            !std::is_sorted(polygons.face_start.begin(), polygons.face_start.end()) ||
            (!polygons.face_line.empty() && polygons.face_line.size() != polygons.face_count()))
            std::abort();
        for (size_t f = 0; f < polygons.face_count(); ++f)
            if (polygons.face_start[f + 1] - polygons.face_start[f] < 3) std::abort();
        for (uint32_t corner : polygons.corners)
            if (corner >= vertices) std::abort();
        const MeshData mesh = build_mesh("input.ply", std::move(polygons));
        check_mesh(mesh);
    } catch (const InputError&) {
    }
}

/// The first byte picks a reader (PNG, JPEG, PPM, PFM, EXR); the rest is the file.
inline void image_input(const uint8_t* data, size_t size) {
    if (size == 0) return;
    static constexpr std::array<const char*, 5> k_names = {"in.png", "in.jpg", "in.ppm", "in.pfm",
                                                           "in.exr"};
    try {
        const Image image = read_image(write_input(data + 1, size - 1, k_names[data[0] % 5]));
        if (image.pixels.size() != static_cast<size_t>(image.width) * image.height) std::abort();
    } catch (const InputError&) {
    }
}

/// glTF JSON or GLB bytes -> MeshData, which must be internally consistent. Input that is not a
/// GLB is read twice: as a .gltf, and as the JSON chunk of a GLB built around it, so mutations of
/// the JSON reach the binary path too.
inline void gltf_input(const uint8_t* data, size_t size) {
    const auto load = [](const std::filesystem::path& path) {
        try {
            check_mesh(load_gltf(path));
        } catch (const InputError&) {
        }
    };
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    if (bytes.starts_with("glTF")) {
        load(write_input(data, size, "input.glb"));
        return;
    }
    load(write_input(data, size, "input.gltf"));
    std::string json(bytes);
    json.resize((json.size() + 3) / 4 * 4, ' ');
    const auto u32 = [](uint32_t v) {
        return std::string{char(v & 0xff), char(v >> 8 & 0xff), char(v >> 16 & 0xff),
                           char(v >> 24)};
    };
    const std::string glb = "glTF" + u32(2) + u32(static_cast<uint32_t>(20 + json.size())) +
                            u32(static_cast<uint32_t>(json.size())) + "JSON" + json;
    load(write_input(reinterpret_cast<const uint8_t*>(glb.data()), glb.size(), "wrapped.glb"));
}

/// The directory write_input() writes into.
inline std::filesystem::path input_dir() {
    const uint8_t none = 0;
    return write_input(&none, 0, "empty").parent_path();
}

/// The three functions below return whether the input loaded (true) or was refused.

/// An image through the scene loader: the first byte picks the format and whether the scene
/// names it as a material's image texture or as an environment map (which checks its shape and
/// texels and builds its sampling tables); the rest is the file.
inline bool scene_texture_input(const uint8_t* data, size_t size) {
    if (size == 0) return false;
    static constexpr std::array<const char*, 6> k_names = {"t.png", "t.jpg", "t.ppm",
                                                           "t.pfm", "t.exr", "t.hdr"};
    const std::string name = k_names[data[0] % 6];
    write_input(data + 1, size - 1, name);
    const bool environment = (data[0] / 6) % 2 == 1;
    const std::string json =
        environment
            ? R"({"lights": [{"type": "environment", "file": ")" + name +
                  R"("}], "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]})"
            : R"({"materials": {"m": {"texture": {"type": "image", "file": ")" + name +
                  R"("}}}, "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                  "material": "m"}]})";
    std::vector<std::string> warnings;
    try {
        parse_scene(json, "fuzz.json", input_dir(), warnings);
        return true;
    } catch (const InputError&) {
        return false;
    }
}

/// A JPEG (progressive ones in the seed corpus): its markers and scans checked, then decoded.
inline bool jpeg_input(const uint8_t* data, size_t size) {
    try {
        const Image image = read_image(write_input(data, size, "in.jpg"));
        if (image.pixels.size() != static_cast<size_t>(image.width) * image.height) std::abort();
        return true;
    } catch (const InputError&) {
        return false;
    }
}

/// An image a glTF model names by URI: the first byte picks PNG or JPEG, the rest is the file,
/// the base-colour texture of a textured triangle whose buffer is an external .bin as well.
inline bool gltf_image_input(const uint8_t* data, size_t size) {
    if (size == 0) return false;
    const std::string image = data[0] % 2 == 0 ? "tex.png" : "tex.jpg";
    write_input(data + 1, size - 1, image);
    // Three positions (x, y, z) and three uvs (u, v) as little-endian floats.
    const std::array<float, 15> floats = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1};
    write_input(reinterpret_cast<const uint8_t*>(floats.data()), sizeof floats, "tri.bin");
    const std::string gltf =
        R"({"asset": {"version": "2.0"}, "meshes": [{"primitives": [{"attributes":
        {"POSITION": 0, "TEXCOORD_0": 1}, "material": 0}]}], "nodes": [{"mesh": 0}],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
        "textures": [{"source": 0}], "images": [{"uri": ")" +
        image + R"("}], "buffers": [{"byteLength": 60, "uri": "tri.bin"}], "bufferViews":
        [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 24}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
        "min": [0, 0, 0], "max": [1, 1, 0]}, {"bufferView": 1, "componentType": 5126, "count": 3,
        "type": "VEC2"}]})";
    try {
        const MeshData mesh = load_gltf(
            write_input(reinterpret_cast<const uint8_t*>(gltf.data()), gltf.size(), "tex.gltf"));
        check_mesh(mesh);
        return true;
    } catch (const InputError&) {
        return false;
    }
}

}  // namespace hikari::fuzz
