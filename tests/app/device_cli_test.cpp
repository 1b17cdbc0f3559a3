// `--device` and `hikari info --devices` (docs/gpu.md): where no CUDA device can run a render,
// the command says so in one line, exits 1 and writes nothing; methods without GPU kernels
// refuse the option by name.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "hikari/core/cuda_devices.h"
#include "run_hikari.h"

namespace {

namespace fs = std::filesystem;
using hikari::testing::run_hikari;
using hikari::testing::RunResult;

class DeviceCli : public ::testing::Test {
  protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() /
                ("hikari_device_" +
                 std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }
    std::string out() const { return (m_dir / "out.png").string(); }
    bool wrote_nothing() const { return fs::is_empty(m_dir); }

    fs::path m_dir;
};

/// The lines of `text` that are not empty.
int line_count(const std::string& text) {
    int lines = 0;
    for (size_t start = 0; start < text.size();) {
        const size_t end = text.find('\n', start);
        const size_t stop = end == std::string::npos ? text.size() : end;
        lines += stop > start ? 1 : 0;
        start = stop + 1;
    }
    return lines;
}

TEST_F(DeviceCli, CudaWithoutADeviceSaysSoInOneLineAndWritesNothing) {
    if (hikari::find_cuda_devices().problem.empty()) GTEST_SKIP() << "a CUDA device is present";
    for (const std::string method : {"raytrace", "path", "zbuffer"}) {
        const RunResult r =
            run_hikari("render --width 32 -m " + method + " --device cuda -o " + out());
        EXPECT_EQ(r.status, 1) << method << ": " << r.output;
        EXPECT_NE(r.output.find("hikari: error: --device cuda: no CUDA device"), std::string::npos)
            << method << ": " << r.output;
        EXPECT_EQ(line_count(r.output), 1) << method << ": " << r.output;
        EXPECT_TRUE(wrote_nothing()) << method;
    }
}

TEST_F(DeviceCli, MethodsWithoutGpuKernelsRefuseTheOption) {
    for (const std::string method : {"scanline", "depthsort", "wireframe"}) {
        const RunResult r =
            run_hikari("render --width 32 -m " + method + " --device cuda -o " + out());
        EXPECT_EQ(r.status, 2) << method << ": " << r.output;
        EXPECT_NE(r.output.find("--device is not an option of method " + method), std::string::npos)
            << r.output;
        EXPECT_TRUE(wrote_nothing()) << method;
    }
}

TEST_F(DeviceCli, CpuIsTheDefaultAndNamedItRendersTheSameFile) {
    const RunResult plain = run_hikari("render --width 32 -o " + out());
    ASSERT_EQ(plain.status, 0) << plain.output;
    const std::string named = (m_dir / "named.png").string();
    const RunResult cpu = run_hikari("render --width 32 --device cpu -o " + named);
    ASSERT_EQ(cpu.status, 0) << cpu.output;
    EXPECT_EQ(fs::file_size(out()), fs::file_size(named));
}

TEST_F(DeviceCli, InfoListsTheDevicesItFinds) {
    const RunResult r = run_hikari("info --devices");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("cpu: "), std::string::npos) << r.output;
    const hikari::CudaDevices cuda = hikari::find_cuda_devices();
    if (cuda.problem.empty())
        EXPECT_NE(r.output.find("cuda 0: " + cuda.devices[0].name), std::string::npos) << r.output;
    else
        EXPECT_NE(r.output.find("cuda: " + cuda.problem), std::string::npos) << r.output;
    const RunResult nothing = run_hikari("info");
    EXPECT_EQ(nothing.status, 2) << nothing.output;
}

}  // namespace
