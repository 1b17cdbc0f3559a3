#pragma once
// Writing an output file whole or not at all: a temporary beside the target, renamed over it.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

namespace hikari {

/// Writes `bytes` to `path` atomically: the data goes to a uniquely named temporary file in the
/// same directory (`.hikari-<hash>-<pid>-<n>.tmp`, see temporary_prefix_for), which is closed
/// and then renamed over `path`. Readers see either the old file or the complete new one, never
/// a partial file. The data is not forced to disk (no fsync): a crash of the operating system
/// soon after may lose the file. Stale temporaries of `path` (remove_stale_temporary_files) are
/// removed first. On any failure the temporary is removed, an existing `path` is left untouched,
/// and InputError is thrown naming `path` and the OS reason; after request_cancel()
/// (core/cancel.h) it stops between chunks or before the rename, removes the temporary and
/// throws Interrupted. Thread-safe.
void write_file_atomically(const std::filesystem::path& path, std::span<const uint8_t> bytes);

/// `.hikari-<16 hex digits>-`: how the name of every temporary of `target` begins. The digits
/// are a hash (64-bit FNV-1a) of `target`'s file name, so the temporary's name has a short fixed
/// length whatever the target's (a 255-byte name still gets one) and says whose it is.
std::string temporary_prefix_for(const std::filesystem::path& target);

/// Removes the temporaries of `target` in its directory whose writing process no longer runs
/// (a `kill -9` during a write leaves one); those of running processes stay. Returns how many
/// were removed. Never throws: an unreadable directory removes nothing.
size_t remove_stale_temporary_files(const std::filesystem::path& target) noexcept;

/// A temporary file beside `target` for a library that writes only to files (libxlsxwriter),
/// named and cleaned up as write_file_atomically's own: a later run's
/// remove_stale_temporary_files removes it when a `kill -9` left it, a signal handler's
/// remove_pending_temporary_files removes it on SIGINT or SIGTERM, and the destructor removes
/// it otherwise. Creates nothing itself: the path is the library's to create.
class TemporaryFile {
  public:
    explicit TemporaryFile(const std::filesystem::path& target);
    ~TemporaryFile();
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;
    const std::string& path() const { return m_path; }

  private:
    std::string m_path;
    int m_slot = -1;  ///< in the signal handler's registry; -1: not registered
};

/// Unlinks every temporary file that a write_file_atomically() call is writing right now.
/// Async-signal-safe (only atomics and unlink(2) on fixed buffers): call it from a SIGINT/SIGTERM
/// handler before exiting, so an interrupted write leaves nothing behind.
void remove_pending_temporary_files() noexcept;

}  // namespace hikari
