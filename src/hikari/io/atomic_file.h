#pragma once
// Writing an output file whole or not at all: a temporary beside the target, renamed over it.

#include <cstdint>
#include <filesystem>
#include <span>

namespace hikari {

/// Writes `bytes` to `path` atomically: the data goes to a uniquely named temporary file in the
/// same directory (`.NAME.tmp-<pid>-<n>`), which is closed and then renamed over `path`. Readers
/// see either the old file or the complete new one, never a partial file. The data is not
/// forced to disk (no fsync): a crash of the operating system soon after may lose the file.
/// On any failure the temporary is removed, an existing `path` is left untouched, and InputError
/// is thrown naming `path` and the OS reason. Thread-safe.
void write_file_atomically(const std::filesystem::path& path, std::span<const uint8_t> bytes);

/// Unlinks every temporary file that a write_file_atomically() call is writing right now.
/// Async-signal-safe (only atomics and unlink(2) on fixed buffers): call it from a SIGINT/SIGTERM
/// handler before exiting, so an interrupted write leaves nothing behind.
void remove_pending_temporary_files() noexcept;

}  // namespace hikari
