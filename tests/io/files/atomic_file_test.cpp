#include "hikari/io/files/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>
#include <vector>

#include "../temp_dir.h"
#include "hikari/core/cancel.h"
#include "hikari/core/error.h"

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

TEST(AtomicFile, NameOfMaximalLengthIsWritten) {
    // The temporary's name has a fixed length: a target of 255 bytes (NAME_MAX) still gets one.
    TempDir dir;
    const std::string name(255, 'n');
    write_file_atomically(dir / name, bytes_of("long"));
    EXPECT_EQ(read_text(dir / name), "long");
    EXPECT_EQ(dir.entry_count(), 1u);
}

TEST(AtomicFile, TemporaryNamesSayWhoseTheyAre) {
    const std::string a = temporary_prefix_for("/x/render.png");
    EXPECT_EQ(a.rfind(".hikari-", 0), 0u) << a;
    EXPECT_EQ(a.size(), std::string(".hikari-0123456789abcdef-").size());
    EXPECT_EQ(a, temporary_prefix_for("render.png"));  // by file name: same directory
    EXPECT_NE(a, temporary_prefix_for("/x/render.exr"));
}

/// The pid of a process that has ended (a child that exits at once, reaped).
pid_t ended_process() {
    const pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    int status = 0;
    ::waitpid(child, &status, 0);
    return child;
}

TEST(AtomicFile, StaleTemporariesOfTheTargetAreRemoved) {
    TempDir dir;
    const std::string prefix = temporary_prefix_for(dir / "a.png");
    const std::string dead = prefix + std::to_string(ended_process()) + "-0.tmp";
    const std::string alive = prefix + std::to_string(::getppid()) + "-0.tmp";
    const std::string other =
        temporary_prefix_for(dir / "b.png") + std::to_string(ended_process()) + "-0.tmp";
    for (const std::string& name : {dead, alive, other}) write_text(dir / name, "partial");
    write_text(dir / "notes.tmp", "someone else's");
    write_file_atomically(dir / "a.png", bytes_of("image"));
    EXPECT_FALSE(std::filesystem::exists(dir / dead)) << "left by a kill -9: removed";
    EXPECT_TRUE(std::filesystem::exists(dir / alive)) << "its writer still runs";
    EXPECT_TRUE(std::filesystem::exists(dir / other)) << "another target's";
    EXPECT_TRUE(std::filesystem::exists(dir / "notes.tmp"));
    EXPECT_EQ(remove_stale_temporary_files(dir / "b.png"), 1u);
    EXPECT_EQ(dir.entry_count(), 3u);  // a.png, alive, notes.tmp
}

TEST(AtomicFile, CancelledWriteLeavesNothing) {
    // In a child process: the cancel flag is process-wide and stays set.
    TempDir dir;
    const pid_t child = ::fork();
    if (child == 0) {
        request_cancel();
        try {
            write_file_atomically(dir / "a.bin", bytes_of("never"));
        } catch (const Interrupted&) {
            ::_exit(std::filesystem::exists(dir / "a.bin") ? 2 : 0);
        } catch (...) {
        }
        ::_exit(1);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "1: no Interrupted thrown, 2: the file was written";
    EXPECT_EQ(dir.entry_count(), 0u);
}

}  // namespace
}  // namespace hikari
