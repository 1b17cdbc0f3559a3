#include "hikari/io/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <string>
#include <vector>

#include "hikari/core/error.h"
#include "temp_dir.h"

namespace hikari {
namespace {

using testing::read_text;
using testing::TempDir;
using testing::write_text;

std::vector<uint8_t> bytes_of(const std::string& s) { return {s.begin(), s.end()}; }

TEST(AtomicFile, WritesNewFile) {
    TempDir dir;
    write_file_atomically(dir / "a.bin", bytes_of("hello"));
    EXPECT_EQ(read_text(dir / "a.bin"), "hello");
    EXPECT_EQ(dir.entry_count(), 1u);  // no temporary left beside it
}

TEST(AtomicFile, ReplacesExistingFile) {
    TempDir dir;
    write_text(dir / "a.bin", "old content, longer than the new");
    write_file_atomically(dir / "a.bin", bytes_of("new"));
    EXPECT_EQ(read_text(dir / "a.bin"), "new");
    EXPECT_EQ(dir.entry_count(), 1u);
}

TEST(AtomicFile, WritesEmptyFile) {
    TempDir dir;
    write_file_atomically(dir / "empty", {});
    EXPECT_TRUE(std::filesystem::exists(dir / "empty"));
    EXPECT_EQ(std::filesystem::file_size(dir / "empty"), 0u);
}

TEST(AtomicFile, MissingDirectoryThrowsAndLeavesNothing) {
    TempDir dir;
    try {
        write_file_atomically(dir / "no" / "such" / "a.bin", bytes_of("x"));
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("a.bin"), std::string::npos) << message;
        EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
    }
    EXPECT_EQ(dir.entry_count(), 0u);
}

TEST(AtomicFile, FailedRenameKeepsTargetAndRemovesTemporary) {
    TempDir dir;
    // The target is a non-empty directory: the temporary is written, rename(2) fails.
    std::filesystem::create_directories(dir / "target" / "inside");
    EXPECT_THROW(write_file_atomically(dir / "target", bytes_of("x")), InputError);
    EXPECT_TRUE(std::filesystem::is_directory(dir / "target" / "inside"));
    EXPECT_EQ(dir.entry_count(), 1u);
}

TEST(AtomicFile, UnwritableDirectoryKeepsExistingTarget) {
    if (::geteuid() == 0) GTEST_SKIP() << "root ignores directory permissions";
    TempDir dir;
    write_text(dir / "a.bin", "old");
    std::filesystem::permissions(
        dir.path(), std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
    EXPECT_THROW(write_file_atomically(dir / "a.bin", bytes_of("new")), InputError);
    std::filesystem::permissions(dir.path(), std::filesystem::perms::owner_all);
    EXPECT_EQ(read_text(dir / "a.bin"), "old");
    EXPECT_EQ(dir.entry_count(), 1u);
}

TEST(AtomicFile, NoPendingTemporariesAfterWrites) {
    TempDir dir;
    write_file_atomically(dir / "a.bin", bytes_of("abc"));
    remove_pending_temporary_files();  // nothing in flight: must not touch finished files
    EXPECT_EQ(read_text(dir / "a.bin"), "abc");
}

}  // namespace
}  // namespace hikari
