// The files a model names, found without loading it (io/models/model_references.h): what the
// command line protects from being overwritten by a render.
#include "hikari/io/models/model_references.h"

#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "../temp_dir.h"
#include "hikari/core/memory_budget.h"

namespace hikari {
namespace {

namespace fs = std::filesystem;

bool names(const std::vector<fs::path>& files, const fs::path& file) {
    return std::find(files.begin(), files.end(), file) != files.end();
}

TEST(ModelReferences, AnObjNamesItsLibrariesAndTheirTextures) {
    const testing::TempDir dir;
    fs::create_directories(dir / "mtl");
    testing::write_text(dir / "mtl/m.mtl",
                        "newmtl a\nmap_Kd -o 0 0 0 tex/kd.png\r\nbump -bm 2 b.png\nKd 1 1 1\n");
    // The mtllib line far into the file, past a block boundary and a very long line.
    std::string obj = "v 0 0 0\n" + std::string(200'000, '#') + "\n";
    for (int i = 0; i < 5000; ++i) obj += "v 1 2 3\n";
    obj += "  mtllib mtl/m.mtl other.mtl\nf 1 1 1\n";
    testing::write_text(dir / "m.obj", obj);
    const std::vector<fs::path> files = model_references(dir / "m.obj");
    EXPECT_TRUE(names(files, dir / "mtl/m.mtl"));
    EXPECT_TRUE(names(files, dir / "other.mtl"));
    EXPECT_TRUE(names(files, dir / "mtl/tex/kd.png"));
    EXPECT_TRUE(names(files, dir / "mtl/b.png"));
    EXPECT_EQ(files.size(), 4u);
}

TEST(ModelReferences, AnObjTheLoaderRefusesBySizeIsNotScanned) {
    // A 4 GiB OBJ under --max-memory 1 took half a minute to scan before the load refused it.
    const testing::TempDir dir;
    testing::write_text(dir / "m.obj", "mtllib m.mtl\n" + std::string(4000, '#') + "\n");
    const double saved = memory_limit();
    set_memory_limit(4000);  // less than the text and its line table, twice the file
    const std::vector<fs::path> refused = model_references(dir / "m.obj");
    set_memory_limit(saved);
    EXPECT_TRUE(refused.empty());
    EXPECT_TRUE(names(model_references(dir / "m.obj"), dir / "m.mtl"));
}

TEST(ModelReferences, AGltfNamesItsExternalImagesAndBuffers) {
    const testing::TempDir dir;
    testing::write_text(dir / "g.gltf", R"({"images": [{"uri": "a.png"}, {"uri": "data:x"}],
                                            "buffers": [{"uri": "b.bin"}]})");
    const std::vector<fs::path> files = model_references(dir / "g.gltf");
    EXPECT_EQ(files, (std::vector<fs::path>{dir / "a.png", dir / "b.bin"}));
    // Not a file, or not JSON: nothing (the loader reports it).
    testing::write_text(dir / "bad.gltf", "{");
    EXPECT_TRUE(model_references(dir / "bad.gltf").empty());
    EXPECT_TRUE(model_references(dir / "missing.obj").empty());
}

}  // namespace
}  // namespace hikari
