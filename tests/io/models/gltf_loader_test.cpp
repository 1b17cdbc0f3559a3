#include "hikari/io/models/gltf_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <variant>
#include <vector>

#include "../../support/expect_near.h"
#include "../../support/input_error.h"
#include "../temp_dir.h"
#include "hikari/core/error.h"

namespace hikari {
namespace {

using nlohmann::json;
using testing::expect_near;
using testing::input_error_of;
using testing::TempDir;
using testing::write_text;

constexpr int k_float = 5126;
constexpr int k_ushort = 5123;
constexpr int k_ubyte = 5121;

std::string base64(const std::string& bytes) {
    static const char* k_digits =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t v = static_cast<uint8_t>(bytes[i]) << 16;
        if (i + 1 < bytes.size()) v |= static_cast<uint8_t>(bytes[i + 1]) << 8;
        if (i + 2 < bytes.size()) v |= static_cast<uint8_t>(bytes[i + 2]);
        out += k_digits[(v >> 18) & 63];
        out += k_digits[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? k_digits[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? k_digits[v & 63] : '=';
    }
    return out;
}

template <class T>
std::string bytes_of(const std::vector<T>& values) {
    std::string out(values.size() * sizeof(T), '\0');
    std::memcpy(out.data(), values.data(), out.size());
    return out;
}

/// A glTF document under construction, with one buffer that collects every accessor's data.
struct GltfBuilder {
    json doc = {{"asset", {{"version", "2.0"}}},
                {"bufferViews", json::array()},
                {"accessors", json::array()},
                {"meshes", json::array()},
                {"nodes", json::array()}};
    std::string bin;

    int view(const std::string& bytes) {
        while (bin.size() % 4 != 0) bin += '\0';
        doc["bufferViews"].push_back(
            {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes.size()}});
        bin += bytes;
        return static_cast<int>(doc["bufferViews"].size()) - 1;
    }
    int accessor(const std::string& bytes, int component_type, size_t count, const char* type,
                 bool normalized = false) {
        json a = {{"bufferView", view(bytes)},
                  {"componentType", component_type},
                  {"count", count},
                  {"type", type}};
        if (normalized) a["normalized"] = true;
        doc["accessors"].push_back(a);
        return static_cast<int>(doc["accessors"].size()) - 1;
    }
    int vec3s(const std::vector<float>& v) {
        return accessor(bytes_of(v), k_float, v.size() / 3, "VEC3");
    }
    int vec2s(const std::vector<float>& v) {
        return accessor(bytes_of(v), k_float, v.size() / 2, "VEC2");
    }
    int ushorts(const std::vector<uint16_t>& v) {
        return accessor(bytes_of(v), k_ushort, v.size(), "SCALAR");
    }

    /// A mesh of one primitive; returns the mesh index.
    int mesh(json primitive) {
        doc["meshes"].push_back({{"primitives", json::array({primitive})}});
        return static_cast<int>(doc["meshes"].size()) - 1;
    }
    int node(json n) {
        doc["nodes"].push_back(n);
        return static_cast<int>(doc["nodes"].size()) - 1;
    }
    void scene(std::vector<int> roots) {
        doc["scenes"] = json::array({{{"nodes", roots}}});
        doc["scene"] = 0;
    }

    /// Writes NAME.gltf into `dir`, the buffer as a data: URI or as NAME.bin beside it.
    std::filesystem::path write(const TempDir& dir, const std::string& name,
                                bool external_bin = false) {
        json d = doc;
        d["buffers"] = json::array({{{"byteLength", bin.size()}}});
        if (external_bin) {
            d["buffers"][0]["uri"] = name + ".bin";
            write_text(dir / (name + ".bin"), bin);
        } else {
            d["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(bin);
        }
        write_text(dir / (name + ".gltf"), d.dump());
        return dir / (name + ".gltf");
    }

    /// The document as a GLB (glTF 2.0 §4.4): header, JSON chunk, BIN chunk.
    std::string glb() const {
        json d = doc;
        d["buffers"] = json::array({{{"byteLength", bin.size()}}});
        std::string text = d.dump();
        while (text.size() % 4 != 0) text += ' ';
        std::string data = bin;
        while (data.size() % 4 != 0) data += '\0';
        const auto u32 = [](uint32_t v) {
            return std::string(reinterpret_cast<const char*>(&v), 4);
        };
        const uint32_t total = 12 + 8 + text.size() + 8 + data.size();
        return "glTF" + u32(2) + u32(total) + u32(text.size()) + "JSON" + text + u32(data.size()) +
               std::string("BIN\0", 4) + data;
    }
};

/// The triangle (0,0,0), (1,0,0), (0,1,0): counter-clockwise seen from +z.
json triangle_primitive(GltfBuilder& b) {
    return {{"attributes", {{"POSITION", b.vec3s({0, 0, 0, 1, 0, 0, 0, 1, 0})}}}};
}

/// The message of the InputError read_gltf(path) throws, or "" when it throws none.
std::string gltf_error(const std::filesystem::path& path) {
    return input_error_of([&] { read_gltf(path); });
}

Vec3 corner(const PolygonMesh& m, size_t face, int k) {
    return m.positions[m.corners[m.face_start[face] + k]];
}

/// N = (P2 − P1) × (P3 − P2), the lecture's face normal (counter-clockwise is the front).
Vec3 face_normal(const PolygonMesh& m, size_t face) {
    return cross(corner(m, face, 1) - corner(m, face, 0), corner(m, face, 2) - corner(m, face, 1));
}

TEST(GltfLoader, NodeHierarchyComposesTranslationRotationScaleAndMatrix) {
    TempDir dir;
    GltfBuilder b;
    const int mesh = b.mesh(triangle_primitive(b));
    // Column-major matrix: a translation by (0, 0, 5).
    const int leaf =
        b.node({{"mesh", mesh}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1}}});
    const double s = std::sin(std::numbers::pi / 4), c = std::cos(std::numbers::pi / 4);
    const int middle =
        b.node({{"children", {leaf}}, {"rotation", {0, 0, s, c}}, {"scale", {2, 2, 2}}});
    const int root = b.node({{"children", {middle}}, {"translation", {10, 0, 0}}});
    b.scene({root});
    const GltfContent g = read_gltf(b.write(dir, "tree"));
    ASSERT_EQ(g.mesh.positions.size(), 3u);
    // p → T(10,0,0) · Rz(90°) · S(2) · T(0,0,5) p
    expect_near(g.mesh.positions[0], {10, 0, 10}, 1e-5f);
    expect_near(g.mesh.positions[1], {10, 2, 10}, 1e-5f);
    expect_near(g.mesh.positions[2], {8, 0, 10}, 1e-5f);
    ASSERT_EQ(g.mesh.face_count(), 1u);
    EXPECT_GT(face_normal(g.mesh, 0).z, 0.0f);
}

TEST(GltfLoader, IndexedAndNonIndexedPrimitivesShareOneMesh) {
    TempDir dir;
    GltfBuilder b;
    // A quad by ushort indices, then a lone triangle without indices.
    const json quad = {
        {"attributes", {{"POSITION", b.vec3s({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0})}}},
        {"indices", b.ushorts({0, 1, 2, 0, 2, 3})}};
    const json tri = triangle_primitive(b);
    b.doc["meshes"].push_back({{"primitives", {quad, tri}}});
    b.scene({b.node({{"mesh", 0}})});
    const GltfContent g = read_gltf(b.write(dir, "two", /*external_bin=*/true));
    EXPECT_EQ(g.mesh.positions.size(), 7u);
    ASSERT_EQ(g.mesh.face_count(), 3u);
    EXPECT_EQ(g.mesh.corners, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 4, 5, 6}));
    EXPECT_EQ(g.mesh.face_material, (std::vector<int32_t>{-1, -1, -1}));
    for (size_t f = 0; f < 3; ++f) EXPECT_GT(face_normal(g.mesh, f).z, 0.0f) << f;
}

TEST(GltfLoader, StripsAndFansBecomeCounterClockwiseTriangles) {
    TempDir dir;
    GltfBuilder b;
    const json strip = {
        {"attributes", {{"POSITION", b.vec3s({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0})}}}, {"mode", 5}};
    const json fan = {{"attributes", {{"POSITION", b.vec3s({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0})}}},
                      {"mode", 6}};
    b.doc["meshes"].push_back({{"primitives", {strip, fan}}});
    b.scene({b.node({{"mesh", 0}})});
    const GltfContent g = read_gltf(b.write(dir, "strip"));
    ASSERT_EQ(g.mesh.face_count(), 4u);
    EXPECT_EQ(g.mesh.corners, (std::vector<uint32_t>{0, 1, 2, 2, 1, 3, 5, 6, 4, 6, 7, 4}));
    for (size_t f = 0; f < 4; ++f) EXPECT_GT(face_normal(g.mesh, f).z, 0.0f) << f;
}

TEST(GltfLoader, MirroredNodeKeepsCounterClockwiseFronts) {
    TempDir dir;
    GltfBuilder b;
    json prim = triangle_primitive(b);
    prim["attributes"]["NORMAL"] = b.vec3s({1, 0, 1, 1, 0, 1, 1, 0, 1});
    b.scene({b.node({{"mesh", b.mesh(prim)}, {"scale", {-1, 1, 1}}})});
    const GltfContent g = read_gltf(b.write(dir, "mirror"));
    ASSERT_EQ(g.mesh.face_count(), 1u);
    EXPECT_GT(face_normal(g.mesh, 0).z, 0.0f);
    expect_near(g.mesh.positions[1], {-1, 0, 0}, 1e-5f);
    // Normals by the inverse transpose, unit length.
    ASSERT_EQ(g.mesh.normals.size(), 3u);
    expect_near(g.mesh.normals[0], Vec3(-1, 0, 1) / std::sqrt(2.0f), 1e-5f);
}

TEST(GltfLoader, NormalsAreZeroForPrimitivesWithout) {
    TempDir dir;
    GltfBuilder b;
    const json bare = triangle_primitive(b);
    json with = triangle_primitive(b);
    with["attributes"]["NORMAL"] = b.vec3s({0, 0, 2, 0, 0, 2, 0, 0, 2});
    b.doc["meshes"].push_back({{"primitives", {bare, with}}});
    b.scene({b.node({{"mesh", 0}})});
    const GltfContent g = read_gltf(b.write(dir, "mixed"));
    ASSERT_EQ(g.mesh.normals.size(), 6u);
    expect_near(g.mesh.normals[0], {0, 0, 0}, 1e-5f);
    expect_near(g.mesh.normals[5], {0, 0, 1}, 1e-5f);
}

TEST(GltfLoader, TexcoordsFlipVToBottomLeftOrigin) {
    TempDir dir;
    GltfBuilder b;
    json prim = triangle_primitive(b);
    // Normalized unsigned bytes: 255 is 1, 51 is 0.2.
    prim["attributes"]["TEXCOORD_0"] = b.accessor(
        bytes_of(std::vector<uint8_t>{0, 0, 255, 51, 0, 255, 0, 0}), k_ubyte, 3, "VEC2", true);
    json prim2 = triangle_primitive(b);
    prim2["attributes"]["TEXCOORD_0"] = b.vec2s({0.25f, 0.1f, 0, 0, 0, 0});
    b.doc["meshes"].push_back({{"primitives", {prim, prim2}}});
    b.scene({b.node({{"mesh", 0}})});
    const GltfContent g = read_gltf(b.write(dir, "uv"));
    ASSERT_EQ(g.mesh.uvs.size(), 6u);
    EXPECT_FLOAT_EQ(g.mesh.uvs[0].y, 1.0f);  // glTF v = 0 is the top row
    EXPECT_FLOAT_EQ(g.mesh.uvs[1].x, 1.0f);
    EXPECT_NEAR(g.mesh.uvs[1].y, 0.8f, 1e-6f);
    EXPECT_FLOAT_EQ(g.mesh.uvs[2].y, 0.0f);
    EXPECT_FLOAT_EQ(g.mesh.uvs[3].x, 0.25f);
    EXPECT_NEAR(g.mesh.uvs[3].y, 0.9f, 1e-6f);
}

TEST(GltfLoader, MaterialsMapMetallicRoughnessToPhong) {
    TempDir dir;
    GltfBuilder b;
    json prim = triangle_primitive(b);
    prim["material"] = 0;
    const json bare = triangle_primitive(b);
    b.doc["meshes"].push_back({{"primitives", {prim, bare}}});
    b.doc["materials"] = {{{"name", "glass"},
                           {"alphaMode", "BLEND"},
                           {"emissiveFactor", {1, 0, 0}},
                           {"pbrMetallicRoughness",
                            {{"baseColorFactor", {0.5, 0.25, 1, 0.25}},
                             {"metallicFactor", 0},
                             {"roughnessFactor", 0.5}}},
                           {"extensions", {{"KHR_materials_ior", {{"ior", 1.33}}}}}}};
    b.scene({b.node({{"mesh", 0}})});
    const GltfContent g = read_gltf(b.write(dir, "mat"));
    EXPECT_EQ(g.mesh.face_material, (std::vector<int32_t>{0, -1}));
    ASSERT_EQ(g.mesh.materials.size(), 1u);
    const Material& m = g.mesh.materials[0];
    EXPECT_EQ(m.name, "glass");
    expect_near(m.kd, {0.5f, 0.25f, 1.0f}, 1e-5f);
    expect_near(m.ka, m.kd, 1e-5f);
    expect_near(m.ks, Vec3(0.04f * 0.25f), 1e-5f);  // 0.04 × (1 − 0.5)²
    // α = r² = 0.25, n = 2/α² − 2 = 30
    EXPECT_NEAR(m.shininess, 30.0f, 1e-3f);
    EXPECT_FLOAT_EQ(m.transparency, 0.75f);
    EXPECT_FLOAT_EQ(m.ior, 1.33f);
    expect_near(m.emission, {1, 0, 0}, 1e-5f);
    EXPECT_FALSE(m.texture.has_value());
}

TEST(GltfLoader, CamerasAndPunctualLights) {
    TempDir dir;
    GltfBuilder b;
    const int mesh = b.mesh(triangle_primitive(b));
    b.doc["cameras"] = {
        {{"type", "perspective"},
         {"perspective", {{"yfov", 0.5}, {"aspectRatio", 1.5}, {"znear", 0.1}}}},
        {{"type", "orthographic"},
         {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}}};
    b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    b.doc["extensions"] = {{"KHR_lights_punctual",
                            {{"lights",
                              {{{"type", "point"}, {"color", {1, 0.5, 0.25}}, {"intensity", 2}},
                               {{"type", "directional"}, {"intensity", 3}}}}}}};
    const double s = std::sin(std::numbers::pi / 4), c = std::cos(std::numbers::pi / 4);
    b.scene({b.node({{"mesh", mesh}}), b.node({{"camera", 0}, {"translation", {0, 0, 5}}}),
             b.node({{"camera", 1}}),
             b.node({{"translation", {1, 2, 3}},
                     {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}),
             b.node({{"rotation", {s, 0, 0, c}},
                     {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}})});
    const GltfContent g = read_gltf(b.write(dir, "cam"));
    ASSERT_EQ(g.cameras.size(), 1u);
    const ModelCamera& cam = g.cameras[0];
    expect_near(cam.camera.eye, {0, 0, 5}, 1e-5f);
    expect_near(cam.camera.look_at, {0, 0, 4}, 1e-5f);
    expect_near(cam.camera.up, {0, 1, 0}, 1e-5f);
    EXPECT_NEAR(cam.camera.fov_y_degrees, 0.5 * 180 / std::numbers::pi, 1e-4);
    ASSERT_TRUE(cam.aspect.has_value());
    EXPECT_FLOAT_EQ(*cam.aspect, 1.5f);
    ASSERT_EQ(g.lights.size(), 2u);
    const auto* point = std::get_if<PointLight>(&g.lights[0]);
    ASSERT_NE(point, nullptr);
    expect_near(point->position, {1, 2, 3}, 1e-5f);
    expect_near(point->intensity, {2, 1, 0.5f}, 1e-5f);
    const auto* sun = std::get_if<DirectionalLight>(&g.lights[1]);
    ASSERT_NE(sun, nullptr);
    expect_near(sun->direction, {0, 1, 0}, 1e-5f);  // −Z turned 90° about +x
    expect_near(sun->intensity, {3, 3, 3}, 1e-5f);
    bool warned = false;
    for (const std::string& w : g.mesh.warnings)
        warned |= w.find("orthographic") != std::string::npos;
    EXPECT_TRUE(warned);
}

/// A glTF file with one KHR_lights_punctual spot light of cone half-angles `inner`, `outer`
/// (radians) on a node turned 90° about +x (its −Z becomes +y) at (1, 2, 3).
std::filesystem::path spot_light_file(const TempDir& dir, double inner, double outer) {
    GltfBuilder b;
    const int mesh = b.mesh(triangle_primitive(b));
    b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    b.doc["extensions"] = {
        {"KHR_lights_punctual",
         {{"lights",
           {{{"type", "spot"},
             {"intensity", 5},
             {"spot", {{"innerConeAngle", inner}, {"outerConeAngle", outer}}}}}}}}};
    const double s = std::sin(std::numbers::pi / 4), c = std::cos(std::numbers::pi / 4);
    b.scene({b.node({{"mesh", mesh}}),
             b.node({{"translation", {1, 2, 3}},
                     {"rotation", {s, 0, 0, c}},
                     {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}})});
    return b.write(dir, "spot");
}

TEST(GltfLoader, SpotLightKeepsItsCone) {
    TempDir dir;
    const GltfContent g = read_gltf(spot_light_file(dir, 0.25, 0.5));
    ASSERT_EQ(g.lights.size(), 1u);
    const auto* spot = std::get_if<SpotLight>(&g.lights[0]);
    ASSERT_NE(spot, nullptr);
    expect_near(spot->position, {1, 2, 3}, 1e-5f);
    expect_near(spot->direction, {0, 1, 0}, 1e-5f);
    expect_near(spot->intensity, {5, 5, 5}, 1e-5f);
    EXPECT_NEAR(spot->inner_angle, 0.25 * 180 / std::numbers::pi, 1e-4);
    EXPECT_NEAR(spot->outer_angle, 0.5 * 180 / std::numbers::pi, 1e-4);
    for (const std::string& w : g.mesh.warnings) EXPECT_EQ(w.find("spot"), std::string::npos);
}

TEST(GltfLoader, SpotLightConeOutOfOrderIsRefused) {
    TempDir dir;
    EXPECT_NE(gltf_error(spot_light_file(dir, 0.5, 0.25)).find("innerConeAngle < outerConeAngle"),
              std::string::npos);
    EXPECT_NE(gltf_error(spot_light_file(dir, 0.1, 2.0)).find("outerConeAngle <= pi/2"),
              std::string::npos);
}

TEST(GltfLoader, MissingBinIsNamed) {
    TempDir dir;
    GltfBuilder b;
    b.scene({b.node({{"mesh", b.mesh(triangle_primitive(b))}})});
    const auto path = b.write(dir, "lost", /*external_bin=*/true);
    std::filesystem::remove(dir / "lost.bin");
    const std::string error = gltf_error(path);
    EXPECT_NE(error.find("lost.gltf"), std::string::npos) << error;
    EXPECT_NE(error.find("lost.bin"), std::string::npos) << error;
}

TEST(GltfLoader, IndexOutOfRangeNamesThePrimitive) {
    TempDir dir;
    GltfBuilder b;
    json prim = triangle_primitive(b);
    prim["indices"] = b.ushorts({0, 1, 7});
    b.scene({b.node({{"mesh", b.mesh(prim)}})});
    const std::string error = gltf_error(b.write(dir, "range"));
    EXPECT_NE(
        error.find(
            "range.gltf: mesh 0 primitive 0: index 7 out of range (the primitive has 3 vertices)"),
        std::string::npos)
        << error;
}

TEST(GltfLoader, AccessorBeyondItsBufferViewIsRefused) {
    TempDir dir;
    GltfBuilder b;
    const json prim = triangle_primitive(b);
    b.doc["accessors"][0]["count"] = 4;  // 48 bytes from a 36-byte view
    b.scene({b.node({{"mesh", b.mesh(prim)}})});
    const std::string error = gltf_error(b.write(dir, "long"));
    EXPECT_NE(error.find("mesh 0 primitive 0: POSITION: accessor 0:"), std::string::npos) << error;
}

TEST(GltfLoader, RefusesWhatItCannotRead) {
    TempDir dir;
    const auto refuses = [&](const std::string& name, auto edit, const std::string& expected) {
        GltfBuilder b;
        b.scene({b.node({{"mesh", b.mesh(triangle_primitive(b))}})});
        edit(b);
        const std::string error = gltf_error(b.write(dir, name));
        EXPECT_NE(error.find(expected), std::string::npos) << name << ": " << error;
    };
    refuses(
        "sparse",
        [](GltfBuilder& b) {
            b.doc["accessors"][0]["sparse"] = {
                {"count", 1},
                {"indices", {{"bufferView", 0}, {"componentType", k_ushort}}},
                {"values", {{"bufferView", 0}}}};
        },
        "sparse accessors are not supported");
    refuses(
        "cycle", [](GltfBuilder& b) { b.doc["nodes"][0]["children"] = {0}; },
        "node 0 is reached twice");
    refuses(
        "ext", [](GltfBuilder& b) { b.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"}; },
        "KHR_draco_mesh_compression");
    refuses(
        "image",
        [](GltfBuilder& b) {
            b.doc["images"] = {{{"bufferView", 0}, {"mimeType", "image/png"}}};
            b.doc["bufferViews"][0]["byteOffset"] = 1000;
        },
        "image 0: bufferView 0: bytes 1000");
    refuses(
        "node", [](GltfBuilder& b) { b.doc["scenes"][0]["nodes"] = {5}; }, "node 5 does not exist");
    refuses(
        "material", [](GltfBuilder& b) { b.doc["meshes"][0]["primitives"][0]["material"] = 3; },
        "mesh 0 primitive 0: material 3 does not exist");

    write_text(dir / "deep.gltf", std::string(1000, '[') + std::string(1000, ']'));
    EXPECT_NE(gltf_error(dir / "deep.gltf").find("nested deeper"), std::string::npos);
    write_text(dir / "bad.gltf", "{\"asset\": ");
    EXPECT_NE(gltf_error(dir / "bad.gltf").find("bad.gltf: invalid JSON"), std::string::npos);
}

TEST(GltfLoader, GlbLoadsAndTruncatedGlbIsRefused) {
    TempDir dir;
    GltfBuilder b;
    b.scene({b.node({{"mesh", b.mesh(triangle_primitive(b))}})});
    const std::string glb = b.glb();
    write_text(dir / "whole.glb", glb);
    const GltfContent g = read_gltf(dir / "whole.glb");
    ASSERT_EQ(g.mesh.positions.size(), 3u);
    expect_near(g.mesh.positions[1], {1, 0, 0}, 1e-5f);
    for (const size_t keep : {size_t{3}, size_t{16}, glb.size() - 4, glb.size() - 40}) {
        write_text(dir / "cut.glb", glb.substr(0, keep));
        const std::string error = gltf_error(dir / "cut.glb");
        EXPECT_NE(error.find("cut.glb"), std::string::npos) << keep << ": " << error;
    }
}

const std::filesystem::path k_box_dir =
    std::filesystem::path(HIKARI_SOURCE_DIR) / "tests/data/models/box-textured";

TEST(GltfLoader, BoxTexturedGltfAndGlbAgree) {
    const GltfContent text = read_gltf(k_box_dir / "BoxTextured.gltf");
    const GltfContent binary = read_gltf(k_box_dir / "BoxTextured.glb");
    for (const GltfContent* g : {&text, &binary}) {
        EXPECT_EQ(g->mesh.positions.size(), 24u);
        EXPECT_EQ(g->mesh.face_count(), 12u);
        EXPECT_EQ(g->mesh.uvs.size(), 24u);
        EXPECT_EQ(g->mesh.normals.size(), 24u);
        ASSERT_EQ(g->mesh.materials.size(), 1u);
        ASSERT_TRUE(g->mesh.materials[0].texture.has_value());
        const auto* image = std::get_if<ImageTexture>(&*g->mesh.materials[0].texture);
        ASSERT_NE(image, nullptr);
        ASSERT_FALSE(image->pyramid->levels.empty());
        EXPECT_EQ(image->pyramid->levels[0].width, 211);
        EXPECT_EQ(image->pyramid->levels[0].height, 211);
        // A closed box: every face's normal points away from its centre (counter-clockwise fronts
        // after the root node's y-up rotation).
        for (size_t f = 0; f < g->mesh.face_count(); ++f) {
            const Vec3 centre =
                (corner(g->mesh, f, 0) + corner(g->mesh, f, 1) + corner(g->mesh, f, 2)) / 3.0f;
            EXPECT_GT(dot(face_normal(g->mesh, f), centre), 0.0f) << f;
        }
    }
    for (size_t i = 0; i < 24; ++i) {
        expect_near(text.mesh.positions[i], binary.mesh.positions[i], 1e-5f);
        EXPECT_FLOAT_EQ(text.mesh.uvs[i].x, binary.mesh.uvs[i].x);
        EXPECT_FLOAT_EQ(text.mesh.uvs[i].y, binary.mesh.uvs[i].y);
    }
}

TEST(GltfLoader, LoadGltfBuildsTheTriangleMesh) {
    const MeshData mesh = load_gltf(k_box_dir / "BoxTextured.gltf");
    EXPECT_EQ(mesh.indices.size(), 12u);
    EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
    EXPECT_EQ(mesh.uvs.size(), mesh.positions.size());
    EXPECT_EQ(mesh.material, std::vector<int32_t>(12, 0));
}

}  // namespace
}  // namespace hikari
