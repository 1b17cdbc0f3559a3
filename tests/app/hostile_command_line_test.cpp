// Hostile use of the command line (issue 26): output names, numeric options, inputs the output
// would replace, and SIGINT / SIGTERM at each stage of a render. Every case checks the exit
// status, the one `hikari: error:` or `hikari: interrupted` line on stderr, and that the output
// directory holds no file afterwards (no image, no temporary).

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "../io/temp_dir.h"
#include "hikari/io/files/atomic_file.h"

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

/// How a run ended: its exit status (128 + N if signal N killed it) and its stderr.
struct Outcome {
    int status = -1;
    std::string err;
};

/// The lines of `text` that begin with `prefix`.
size_t lines_starting_with(const std::string& text, std::string_view prefix) {
    std::istringstream in(text);
    size_t n = 0;
    for (std::string line; std::getline(in, line);) n += line.starts_with(prefix) ? 1 : 0;
    return n;
}

using hikari::testing::read_text;

/// The names in `dir`, hidden ones included, for failure messages.
std::string listing(const fs::path& dir) {
    std::string names;
    for (const auto& e : fs::directory_iterator(dir)) names += e.path().filename().string() + " ";
    return names;
}

/// A grid of `n` x `n` squares, 2 n² triangles, as OBJ text: big enough that loading it and
/// building its BVH each take a good part of a second.
void write_grid_obj(const fs::path& path, int n) {
    std::FILE* f = std::fopen(path.c_str(), "w");
    ASSERT_NE(f, nullptr);
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) std::fprintf(f, "v %d %d %d\n", i, (i * j) % 7, j);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i + 1, b = a + 1, c = a + n + 2, d = a + n + 1;
            std::fprintf(f, "f %d %d %d\nf %d %d %d\n", a, b, c, a, c, d);
        }
    std::fclose(f);
}

class HostileCommandLine : public ::testing::Test {
  protected:
    /// One big mesh for the whole suite, written once: 1.5 million triangles.
    static void SetUpTestSuite() {
        s_inputs =
            fs::temp_directory_path() / ("hikari_hostile_cl_inputs_" + std::to_string(getpid()));
        fs::create_directories(s_inputs);
        write_grid_obj(s_inputs / "big.obj", 866);
        // A scene around it; --ground's warning about it marks the end of loading on stderr.
        std::ofstream(s_inputs / "big.json")
            << R"({"objects": [{"type": "mesh", "file": "big.obj"}]})";
    }
    static void TearDownTestSuite() { fs::remove_all(s_inputs); }

    void SetUp() override {
        m_dir = fs::temp_directory_path() /
                ("hikari_hostile_cl_" +
                 std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir / "out");
    }
    void TearDown() override { fs::remove_all(m_dir); }

    /// `name` in the output directory.
    std::string out(const std::string& name) const { return (m_dir / "out" / name).string(); }
    fs::path log() const { return m_dir / "stderr.txt"; }

    /// Starts `hikari ARGS` (no shell) in `cwd`, stdout to /dev/null, stderr to log().
    pid_t start(const std::vector<std::string>& args, const fs::path& cwd = {}) const {
        std::vector<char*> argv{const_cast<char*>(HIKARI_CLI_PATH)};
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        const std::string err = log().string();
        const pid_t child = fork();
        if (child == 0) {
            const int fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            const int null = ::open("/dev/null", O_WRONLY);
            if (fd < 0 || null < 0 || (!cwd.empty() && ::chdir(cwd.c_str()) != 0)) _exit(126);
            ::dup2(fd, STDERR_FILENO);
            ::dup2(null, STDOUT_FILENO);
            ::execv(HIKARI_CLI_PATH, argv.data());
            _exit(127);
        }
        return child;
    }

    /// Waits for `child` (killing it after 30 s: a hang fails the test) and reads its stderr.
    Outcome finish(pid_t child) const {
        int raw = 0;
        const auto deadline = std::chrono::steady_clock::now() + 30s;
        while (waitpid(child, &raw, WNOHANG) == 0) {
            if (std::chrono::steady_clock::now() > deadline) {
                kill(child, SIGKILL);
                waitpid(child, &raw, 0);
                ADD_FAILURE() << "hikari did not end within 30 s";
                break;
            }
            std::this_thread::sleep_for(5ms);
        }
        return {WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw), read_text(log())};
    }

    Outcome run(const std::vector<std::string>& args, const fs::path& cwd = {}) const {
        return finish(start(args, cwd));
    }

    /// Waits until stderr holds `marker` (at most 20 s).
    void wait_for_marker(const std::string& marker) const {
        const auto deadline = std::chrono::steady_clock::now() + 20s;
        while (read_text(log()).find(marker) == std::string::npos &&
               std::chrono::steady_clock::now() < deadline)
            std::this_thread::sleep_for(2ms);
    }

    /// The run ended on `signal` as it should: 128 + signal, the one line, nothing left.
    void expect_interrupted(const Outcome& r, int signal) const {
        EXPECT_EQ(r.status, 128 + signal) << r.err;
        EXPECT_EQ(lines_starting_with(r.err, "hikari: interrupted"), 1u) << r.err;
        EXPECT_EQ(lines_starting_with(r.err, "hikari: error:"), 0u) << r.err;
        EXPECT_TRUE(fs::is_empty(m_dir / "out")) << "left: " << listing(m_dir / "out");
    }

    /// `render ARGS` is a usage error: status 2, one error line holding `message`, short, and
    /// nothing written.
    void expect_usage_error(const std::vector<std::string>& args, const std::string& message,
                            const fs::path& cwd = {}) const {
        const Outcome r = run(args, cwd);
        std::string shown;
        size_t longest = 0;  // the line may name the longest argument, then say little more
        for (const std::string& a : args) {
            shown += a.substr(0, 40) + " ";
            longest = std::max(longest, a.size());
        }
        EXPECT_EQ(r.status, 2) << shown << ": " << r.err;
        EXPECT_EQ(lines_starting_with(r.err, "hikari: error:"), 1u) << shown << ": " << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << shown << ": " << r.err;
        EXPECT_LT(r.err.find('\n'), longest + 200) << "one short line: " << r.err;
        EXPECT_TRUE(fs::is_empty(m_dir / "out")) << shown << " left: " << listing(m_dir / "out");
    }

    static fs::path s_inputs;
    fs::path m_dir;
};

fs::path HostileCommandLine::s_inputs;

TEST_F(HostileCommandLine, OutputMistakesAreUsageErrorsFoundBeforeAnyWork) {
    // big.json would take seconds to load: each refusal comes before it.
    const std::string scene = (s_inputs / "big.json").string();
    expect_usage_error({"render", scene, "-o", out("x.bmp")}, "unknown output format '.bmp'");
    expect_usage_error({"render", scene, "-o", out("x")}, "unknown output format (no extension)");
    expect_usage_error({"render", scene, "-o", (m_dir / "out").string()}, "is a directory");
    expect_usage_error({"render", scene, "-o", out("missing/dir/x.png")},
                       "the directory " + out("missing/dir") + " does not exist");
    expect_usage_error({"render", scene, "-o", out(std::string(253, 'n') + ".png")},
                       "the file name is 257 bytes long");
}

TEST_F(HostileCommandLine, NameOfTheLongestLengthIsWritten) {
    // The temporary's name has a fixed length, however long the target's.
    const std::string name = std::string(251, 'n') + ".png";
    const Outcome r = run({"render", "--width", "8", "-q", "-o", out(name)});
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(fs::exists(out(name)));
    EXPECT_EQ(listing(m_dir / "out"), name + " ");
}

TEST_F(HostileCommandLine, StaleTemporariesOfTheTargetAreRemoved) {
    // What a kill -9 during a write leaves: a temporary of a process that no longer runs.
    const pid_t gone = fork();
    if (gone == 0) _exit(0);
    waitpid(gone, nullptr, 0);
    const std::string stale =
        out(hikari::temporary_prefix_for(out("a.png")) + std::to_string(gone) + "-0.tmp");
    std::ofstream(stale) << "half an image";
    const Outcome r = run({"render", "--width", "8", "-q", "-o", out("a.png")});
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(listing(m_dir / "out"), "a.png ");
}

TEST_F(HostileCommandLine, RefusesToOverwriteWhatTheRenderReads) {
    // A scene file named .png, rendered without -o: its default output is itself.
    const std::string text = R"({"objects": [{"type": "sphere", "center": [0, 0, -3]}]})";
    std::ofstream(out("scene.png")) << text;
    const Outcome own = run({"render", "scene.png", "--width", "8"}, m_dir / "out");
    EXPECT_EQ(own.status, 2) << own.err;
    EXPECT_NE(own.err.find("refusing to overwrite the scene file"), std::string::npos) << own.err;
    EXPECT_EQ(read_text(out("scene.png")), text);
    // A texture the scene names.
    const Outcome made = run({"render", "--width", "4", "--height", "4", "-q", "-o", out("t.png")});
    ASSERT_EQ(made.status, 0) << made.err;
    const std::string texture = read_text(out("t.png"));
    std::ofstream(out("textured.json"))
        << R"({"materials": {"m": {"texture": {"type": "image", "file": "t.png"}}},
              "objects": [{"type": "sphere", "center": [0, 0, -3], "material": "m"}]})";
    const Outcome tex = run({"render", out("textured.json"), "-o", out("t.png")});
    EXPECT_EQ(tex.status, 2) << tex.err;
    EXPECT_EQ(lines_starting_with(tex.err, "hikari: error:"), 1u) << tex.err;
    EXPECT_NE(tex.err.find("refusing to overwrite a file the scene reads"), std::string::npos)
        << tex.err;
    EXPECT_EQ(read_text(out("t.png")), texture);
    // A model file as its own output: refused (its extension is no image's), left as it was.
    const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    std::ofstream(out("tri.obj")) << obj;
    EXPECT_EQ(run({"render", out("tri.obj"), "-o", out("tri.obj")}).status, 2);
    EXPECT_EQ(read_text(out("tri.obj")), obj);
    EXPECT_EQ(listing(m_dir / "out").size(),
              std::string("scene.png t.png textured.json tri.obj ").size())
        << listing(m_dir / "out");
}

TEST_F(HostileCommandLine, NumericOptionsAreCheckedWithShortMessages) {
    const std::vector<std::vector<std::string>> cases = {
        {"--max-memory", "nan"},   {"--max-memory", "0"},
        {"--max-memory", "-1"},    {"--exposure", "nan"},
        {"--exposure", "inf"},     {"--spp", "0"},
        {"--threads", "0"},        {"--width", "-1"},
        {"--height", "1e3"},       {"--width", "99999999999"},
        {"--depth-cue", "nan,1"},  {"--depth-cue", "1,inf"},
        {"--depth-range", "-1,2"}, {"--camera-from", "nan,0,0"},
        {"--look-at", "0,1e39,0"}, {"--crease-angle", "nan"},
        {"--tessellation", "2"},   {"--light-samples", "x"},
        {"--max-depth", "-3"},
    };
    for (std::vector<std::string> args : cases) {
        args.insert(args.begin(), "render");
        args.insert(args.end(), {"-o", out("x.png")});
        expect_usage_error(args, "expected ");
    }
    expect_usage_error({"render", "-m", "wireframe", "--line-width", "nan", "-o", out("x.png")},
                       "--line-width: expected a number from 0.01 to 1000");
    expect_usage_error({"render", "-m", "wireframe", "--line-color", "1,nan,0", "-o", out("x.png")},
                       "--line-color: expected ");
    expect_usage_error({"render", "-m", "path", "--clamp", "1e40", "-o", out("x.png")},
                       "--clamp: expected ");
}

TEST_F(HostileCommandLine, SigtermWhileLoadingExits143) {
    const pid_t child = start({"render", (s_inputs / "big.obj").string(), "-o", out("a.png")});
    std::this_thread::sleep_for(300ms);  // loading 1.5 million triangles takes seconds
    kill(child, SIGTERM);
    expect_interrupted(finish(child), SIGTERM);
}

TEST_F(HostileCommandLine, TwoSigintsWhileLoadingExit130WithOneLine) {
    const pid_t child = start({"render", (s_inputs / "big.obj").string(), "-o", out("a.exr")});
    std::this_thread::sleep_for(200ms);
    kill(child, SIGINT);
    std::this_thread::sleep_for(50ms);
    kill(child, SIGINT);
    expect_interrupted(finish(child), SIGINT);
}

TEST_F(HostileCommandLine, SigintWhileBuildingTheBvhExits130) {
    // The warning about --ground comes right after loading, just before the BVH build.
    const pid_t child = start({"render", (s_inputs / "big.json").string(), "--ground", "--width",
                               "16", "-o", out("a.png")});
    wait_for_marker("--ground adds a plane");
    kill(child, SIGINT);
    expect_interrupted(finish(child), SIGINT);
}

TEST_F(HostileCommandLine, SigtermWhileTracingExits143) {
    const pid_t child =
        start({"render", "-m", "path", "--spp", "4096", "--width", "256", "-o", out("a.png")});
    std::this_thread::sleep_for(400ms);
    kill(child, SIGTERM);
    expect_interrupted(finish(child), SIGTERM);
}

TEST_F(HostileCommandLine, SigintWhileTracingExits130) {
    const pid_t child =
        start({"render", "-m", "path", "--spp", "4096", "--width", "256", "-o", out("a.pfm")});
    std::this_thread::sleep_for(400ms);
    kill(child, SIGINT);
    expect_interrupted(finish(child), SIGINT);
}

TEST_F(HostileCommandLine, SigtermWhileEncodingExits143) {
    // A 9-megapixel sphere renders in a fraction of a second; its EXR takes about two to encode.
    const pid_t child =
        start({"render", "--width", "3000", "--height", "3000", "-o", out("a.exr")});
    std::this_thread::sleep_for(900ms);
    kill(child, SIGTERM);
    expect_interrupted(finish(child), SIGTERM);
}

}  // namespace
