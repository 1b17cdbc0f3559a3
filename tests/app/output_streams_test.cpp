// A full or closed stdout or stderr (issue 41, item 1): the program never aborts; a report that
// cannot reach stdout ends with exit status 1 and a line on stderr saying why; a line that
// cannot reach stderr is dropped, the work is done as usual, and the exit status is 1 (as GNU's
// close_stdout does: the status is all that can still say a line was lost).

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "run_hikari.h"

namespace {

namespace fs = std::filesystem;
using hikari::testing::run_hikari_redirected;
using hikari::testing::RunResult;

/// The line a command prints when its report could not reach stdout (with the reason where the
/// system said it: "No space left on device" here).
constexpr const char* k_stdout_failed = "hikari: error: cannot write to standard output";

class OutputStreams : public ::testing::Test {
  protected:
    void SetUp() override { fs::create_directories(m_dir); }
    void TearDown() override { fs::remove_all(m_dir); }

    std::string path(const std::string& name) const { return (m_dir / name).string(); }

    /// The lecture's assignment scene of the repository.
    static std::string scene() {
        return std::string(HIKARI_SOURCE_DIR) + "/scenes/assignment.json";
    }

    /// `hikari ARGS` with stdout on /dev/full: its status and what it said on stderr.
    static RunResult with_full_stdout(const std::string& args) {
        return run_hikari_redirected(args, "2>&1 >/dev/full");
    }

    /// A directory of the test's own (its name is the test's).
    const fs::path m_dir =
        fs::temp_directory_path() /
        ("hikari_streams_" +
         std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
};

TEST_F(OutputStreams, FullStderrDoesNotStopARenderButFailsIt) {
    const RunResult r =
        run_hikari_redirected("render -o " + path("x.png") + " --width 8 --stats", "2>/dev/full");
    EXPECT_EQ(r.status, 1);
    EXPECT_TRUE(fs::exists(path("x.png")));
}

TEST_F(OutputStreams, QuietRenderWithAFullStderrSucceeds) {
    // Nothing is lost where nothing is said.
    const RunResult r =
        run_hikari_redirected("render -o " + path("x.png") + " --width 8 -q", "2>/dev/full");
    EXPECT_EQ(r.status, 0);
    EXPECT_TRUE(fs::exists(path("x.png")));
}

TEST_F(OutputStreams, WarningsOnAFullStderrFailTheRender) {
    // --ground on a scene file (not a model) is ignored with a warning, even with -q.
    const RunResult r = run_hikari_redirected(
        "render -o " + path("x.png") + " --width 8 -q --ground", "2>/dev/full");
    EXPECT_EQ(r.status, 1);
    EXPECT_TRUE(fs::exists(path("x.png")));
}

TEST_F(OutputStreams, ClosedStderrDoesNotStopARenderNorReceiveItsFile) {
    const RunResult r =
        run_hikari_redirected("render -o " + path("x.png") + " --width 8 --stats", "2>&-");
    EXPECT_EQ(r.status, 1);
    ASSERT_TRUE(fs::exists(path("x.png")));
    // Had a file the render writes taken descriptor 2, the lines for stderr would be in it.
    const RunResult cmp =
        run_hikari_redirected("compare " + path("x.png") + " " + path("x.png") + " --psnr", "2>&1");
    EXPECT_EQ(cmp.status, 0) << cmp.output;
}

TEST_F(OutputStreams, ErrorsWithAFullStderrKeepTheirStatus) {
    EXPECT_EQ(run_hikari_redirected("render " + path("missing.json"), "2>/dev/full").status, 1);
    EXPECT_EQ(run_hikari_redirected("render --width 0", "2>/dev/full").status, 2);
    EXPECT_EQ(run_hikari_redirected("info " + scene(), ">/dev/full 2>/dev/full").status, 1);
}

TEST_F(OutputStreams, ReportsOnAFullStdoutFail) {
    ASSERT_EQ(run_hikari_redirected("render -o " + path("a.png") + " --width 8 -q", "").status, 0);
    for (const std::string& args :
         {"info " + scene(), "compare " + path("a.png") + " " + path("a.png"),
          "compare " + path("a.png") + " " + path("a.png") + " --psnr",
          "explain " + scene() + " -m depthsort --width 8",
          "explain " + scene() + " -m zbuffer --pixel 4,4 --width 8", std::string("--help"),
          std::string("--version")}) {
        const RunResult r = with_full_stdout(args);
        EXPECT_EQ(r.status, 1) << args;
        EXPECT_NE(r.output.find(k_stdout_failed), std::string::npos) << args << ": " << r.output;
    }
}

TEST_F(OutputStreams, PrintMatricesOnAFullStdoutFailsAfterTheRender) {
    const RunResult r =
        with_full_stdout("render --print-matrices --width 8 -q -o " + path("m.png"));
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find(k_stdout_failed), std::string::npos) << r.output;
    EXPECT_TRUE(fs::exists(path("m.png")));
}

TEST_F(OutputStreams, ClosedStdoutFails) {
    const RunResult r = run_hikari_redirected("info " + scene(), "2>&1 >&-");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("hikari: error: cannot write to standard output: Bad file descriptor"),
              std::string::npos)
        << r.output;
}

}  // namespace
