#include "hikari/io/models/model_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <vector>

#include "../temp_dir.h"
#include "hikari/core/error.h"

namespace hikari {
namespace {

/// A bumpy grid of triangles: the same mesh is written in every format.
struct Grid {
    std::vector<Vec3> positions;
    std::vector<std::array<uint32_t, 3>> triangles;
};

Grid bumpy_grid(int n) {
    Grid g;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            g.positions.push_back({float(i) / n, 0.1f * std::sin(float(i * j)), float(j) / n});
    auto at = [n](int i, int j) { return uint32_t(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            g.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            g.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    return g;
}

void write_obj(const std::filesystem::path& file, const Grid& g) {
    std::ofstream out(file);
    out.precision(9);
    for (const Vec3& p : g.positions) out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (const auto& t : g.triangles)
        out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

/// Binary big-endian, the byte order that needs swapping on these machines.
void write_ply(const std::filesystem::path& file, const Grid& g) {
    std::ofstream out(file, std::ios::binary);
    out << "ply\nformat binary_big_endian 1.0\nelement vertex " << g.positions.size()
        << "\nproperty float x\nproperty float y\nproperty float z\nelement face "
        << g.triangles.size() << "\nproperty list uchar uint vertex_indices\nend_header\n";
    auto put32 = [&out](uint32_t v) {
        const char b[4] = {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
        out.write(b, 4);
    };
    for (const Vec3& p : g.positions)
        for (float c : {p.x, p.y, p.z}) {
            uint32_t bits;
            std::memcpy(&bits, &c, 4);
            put32(bits);
        }
    for (const auto& t : g.triangles) {
        out.put(3);
        for (uint32_t v : t) put32(v);
    }
}

void write_gltf(const std::filesystem::path& file, const Grid& g) {
    const size_t position_bytes = g.positions.size() * sizeof(Vec3);
    const size_t index_bytes = g.triangles.size() * 3 * sizeof(uint32_t);
    std::ofstream bin(file.parent_path() / "grid.bin", std::ios::binary);
    bin.write(reinterpret_cast<const char*>(g.positions.data()), std::streamsize(position_bytes));
    bin.write(reinterpret_cast<const char*>(g.triangles.data()), std::streamsize(index_bytes));
    Vec3 lo(INFINITY), hi(-INFINITY);
    for (const Vec3& p : g.positions) lo = min(lo, p), hi = max(hi, p);
    const nlohmann::json doc = {
        {"asset", {{"version", "2.0"}}},
        {"buffers", {{{"uri", "grid.bin"}, {"byteLength", position_bytes + index_bytes}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", position_bytes}},
          {{"buffer", 0}, {"byteOffset", position_bytes}, {"byteLength", index_bytes}}}},
        {"accessors",
         {{{"bufferView", 0},
           {"componentType", 5126},
           {"count", g.positions.size()},
           {"type", "VEC3"},
           {"min", {lo.x, lo.y, lo.z}},
           {"max", {hi.x, hi.y, hi.z}}},
          {{"bufferView", 1},
           {"componentType", 5125},
           {"count", g.triangles.size() * 3},
           {"type", "SCALAR"}}}},
        {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"scenes", {{{"nodes", {0}}}}},
        {"scene", 0}};
    std::ofstream(file) << doc.dump();
}

TEST(ModelFile, TheSameMeshInEveryFormatLoadsTheSame) {
    testing::TempDir dir;
    const Grid grid = bumpy_grid(12);
    write_obj(dir / "grid.obj", grid);
    write_ply(dir / "grid.ply", grid);
    write_gltf(dir / "grid.gltf", grid);
    const MeshData obj = load_model(dir / "grid.obj");
    for (const char* name : {"grid.ply", "grid.gltf"}) {
        SCOPED_TRACE(name);
        const MeshData other = load_model(dir / name);
        ASSERT_EQ(other.indices.size(), obj.indices.size());
        // Same triangles in the same order (so the same primitive ids), same corners, same
        // computed normals.
        for (size_t t = 0; t < obj.indices.size(); ++t)
            for (int k = 0; k < 3; ++k) {
                const Vec3 a = obj.positions[obj.indices[t][k]];
                const Vec3 b = other.positions[other.indices[t][k]];
                EXPECT_NEAR(a.x, b.x, 1e-6f);
                EXPECT_NEAR(a.y, b.y, 1e-6f);
                EXPECT_NEAR(a.z, b.z, 1e-6f);
                EXPECT_NEAR(dot(obj.normals[obj.indices[t][k]], other.normals[other.indices[t][k]]),
                            1.0f, 1e-5f);
            }
    }
}

TEST(ModelFile, ExtensionsChooseTheLoader) {
    EXPECT_TRUE(is_model_file("a/b.OBJ"));
    EXPECT_TRUE(is_model_file("b.ply"));
    EXPECT_TRUE(is_model_file("b.gltf"));
    EXPECT_TRUE(is_model_file("b.GLB"));
    EXPECT_FALSE(is_model_file("scene.json"));
    EXPECT_FALSE(is_model_file("mesh"));
    try {
        load_model("mesh.stl");
        FAIL() << "an STL file was accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "mesh.stl: not a model file: expected one of .obj, .ply, .gltf, .glb");
    }
}

}  // namespace
}  // namespace hikari
