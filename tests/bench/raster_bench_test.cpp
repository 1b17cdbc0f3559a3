#include "hikari/bench/raster_bench.h"

#include <tbb/global_control.h>

#include <gtest/gtest.h>

namespace hikari {
namespace {

const BenchMesh& bunny() {
    static const BenchMesh mesh =
        load_bench_mesh(HIKARI_SOURCE_DIR "/scenes/models/stanford-bunny.obj");
    return mesh;
}

RasterBenchSettings one_frame(bool shadow) {
    RasterBenchSettings s;
    s.shadow = shadow;
    s.warmup_frames = 0;
    s.timed_frames = 1;
    return s;
}

// SPEC §6's validation: llvmpipe covers 389,877 pixels of the bunny's frame; a rasterizer with
// the same top-left rule and float setup matches to within a few edge pixels.
TEST(RasterBench, TheBunnyCoversTheSpecsPixels) {
    const RasterBenchResult r = run_raster_bench(bunny(), "bunny", one_frame(false));
    EXPECT_NEAR(static_cast<double>(r.covered_pixels), 389877.0, 8.0);
    EXPECT_EQ(r.shadowed_pixels, 0u);
    EXPECT_EQ(r.frame_ms.size(), 1u);
    EXPECT_NE(r.to_json().find("\"variant\": \"plain\""), std::string::npos);
}

TEST(RasterBench, TheShadowPassDarkensPartOfTheSameCoverage) {
    const RasterBenchResult plain = run_raster_bench(bunny(), "bunny", one_frame(false));
    const RasterBenchResult shadow = run_raster_bench(bunny(), "bunny", one_frame(true));
    EXPECT_EQ(shadow.covered_pixels, plain.covered_pixels);
    // The light comes from the upper left and front: the ear and the body shadow the bunny's
    // right side, but most of what the camera sees is lit.
    EXPECT_GT(shadow.shadowed_pixels, plain.covered_pixels / 20);
    EXPECT_LT(shadow.shadowed_pixels, plain.covered_pixels / 2);
}

TEST(RasterBench, TheFrameDoesNotDependOnThreadsOrInstructionSet) {
    Srgb8Image reference;
    {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        RasterBenchSettings s = one_frame(true);
        s.simd = SimdLevel::portable;
        run_raster_bench(bunny(), "bunny", s, &reference);
    }
    for (const SimdLevel level : supported_simd_levels()) {
        Srgb8Image image;
        RasterBenchSettings s = one_frame(true);
        s.simd = level;
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        run_raster_bench(bunny(), "bunny", s, &image);
        EXPECT_TRUE(std::equal(image.bytes.begin(), image.bytes.end(), reference.bytes.begin()))
            << simd_level_name(level);
    }
}

}  // namespace
}  // namespace hikari
