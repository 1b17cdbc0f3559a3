// Replays every input the fuzzers (fuzz/, scripts/fuzz.sh) ever broke hikari with. Under the
// sanitizer build in CI a regression shows up as a sanitizer report; in any build as a crash.

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "../../fuzz/fuzz_inputs.h"

namespace hikari {
namespace {

namespace fs = std::filesystem;

template <class Fn>
int replay(const std::string& target, Fn&& run) {
    const fs::path dir = fs::path(HIKARI_SOURCE_DIR) / "tests/data/fuzz-regressions" / target;
    int count = 0;
    if (!fs::exists(dir)) return 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        std::ifstream in(entry.path(), std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), {});
        SCOPED_TRACE(entry.path().string());
        run(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
        ++count;
    }
    return count;
}

TEST(FuzzRegression, SceneJsonInputs) { replay("scene_json", fuzz::scene_json_input); }
TEST(FuzzRegression, ObjInputs) { replay("obj", fuzz::obj_input); }
TEST(FuzzRegression, MtlInputs) { replay("mtl", fuzz::mtl_input); }
TEST(FuzzRegression, ImageInputs) { EXPECT_GE(replay("image", fuzz::image_input), 1); }
TEST(FuzzRegression, GltfInputs) { EXPECT_GE(replay("gltf", fuzz::gltf_input), 1); }
TEST(FuzzRegression, PlyInputs) { EXPECT_GE(replay("ply", fuzz::ply_input), 1); }

}  // namespace
}  // namespace hikari
