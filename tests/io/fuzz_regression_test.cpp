// Replays every input the fuzzers (fuzz/, scripts/fuzz.sh) ever broke hikari with. Under the
// sanitizer build in CI a regression shows up as a sanitizer report; in any build as a crash.

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "../../fuzz/fuzz_inputs.h"

namespace hikari {
namespace {

namespace fs = std::filesystem;

template <class Fn>
int replay(const std::string& target, Fn&& run,
           const std::string& folder = "tests/data/fuzz-regressions") {
    const fs::path dir = fs::path(HIKARI_SOURCE_DIR) / folder / target;
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
TEST(FuzzRegression, JpegInputs) { EXPECT_GE(replay("jpeg", fuzz::jpeg_input), 1); }

/// How many of the seeds in fuzz/corpus/`target` `load` loads (returns true for).
template <class Fn>
std::pair<int, int> loaded_seeds(const std::string& target, Fn&& load) {
    int loaded = 0;
    const int count = replay(
        target, [&](const uint8_t* data, size_t size) { loaded += load(data, size) ? 1 : 0; },
        "fuzz/corpus");
    return {loaded, count};
}

// The seed corpora of the targets for images named by scenes and models: each seed is an image
// that loads, so the harness reaches the decoders.
TEST(FuzzSeeds, SceneTextureSeedsLoad) {
    const auto [loaded, count] = loaded_seeds("scene_texture", fuzz::scene_texture_input);
    EXPECT_GE(count, 3);
    EXPECT_EQ(loaded, count);
}
TEST(FuzzSeeds, JpegSeedsLoad) {
    const auto [loaded, count] = loaded_seeds("jpeg", fuzz::jpeg_input);
    EXPECT_GE(count, 3);
    EXPECT_EQ(loaded, count);
}
TEST(FuzzSeeds, GltfImageSeedsLoad) {
    const auto [loaded, count] = loaded_seeds("gltf_image", fuzz::gltf_image_input);
    EXPECT_GE(count, 2);
    EXPECT_EQ(loaded, count);
}

}  // namespace
}  // namespace hikari
