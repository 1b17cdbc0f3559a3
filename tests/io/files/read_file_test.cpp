#include "hikari/io/files/read_file.h"

#include <sys/stat.h>

#include <gtest/gtest.h>

#include <chrono>

#include "../temp_dir.h"
#include "hikari/core/error.h"

namespace hikari {
namespace {

using testing::TempDir;

/// The InputError message of reading `path` ("" when it reads).
std::string error_reading(const std::filesystem::path& path, std::uintmax_t max_bytes = 1 << 20) {
    try {
        read_file_bytes(path, max_bytes);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(ReadFile, ReadsARegularFile) {
    TempDir dir;
    testing::write_text(dir / "a.txt", "hello");
    EXPECT_EQ(read_file_bytes(dir / "a.txt"), "hello");
}

TEST(ReadFile, RefusesWhatIsNotARegularFileAtOnce) {
    TempDir dir;
    ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
    const auto start = std::chrono::steady_clock::now();
    // A FIFO would block until a writer comes, /dev/zero never ends.
    const std::string fifo = error_reading(dir / "pipe");
    EXPECT_NE(fifo.find("pipe: cannot read: a FIFO"), std::string::npos) << fifo;
    const std::string zero = error_reading("/dev/zero");
    EXPECT_NE(zero.find("/dev/zero: cannot read: a device"), std::string::npos) << zero;
    const std::string directory = error_reading(dir.path());
    EXPECT_NE(directory.find("cannot read: a directory"), std::string::npos) << directory;
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
}

TEST(ReadFile, RefusesFilesLongerThanTheLimit) {
    TempDir dir;
    testing::write_text(dir / "big.txt", std::string(100, 'x'));
    const std::string e = error_reading(dir / "big.txt", 10);
    EXPECT_NE(e.find("larger than the limit of 10 bytes"), std::string::npos) << e;
    EXPECT_EQ(read_file_bytes(dir / "big.txt", 100).size(), 100u);
}

TEST(ReadFile, MissingFileNamesTheReason) {
    TempDir dir;
    const std::string e = error_reading(dir / "gone.obj");
    EXPECT_NE(e.find("gone.obj: cannot read: No such file or directory"), std::string::npos) << e;
}

}  // namespace
}  // namespace hikari
