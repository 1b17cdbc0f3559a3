#pragma once
// Reading an input file into memory, with an error that names the file and the OS reason.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include "hikari/io/files/input_limits.h"

namespace hikari {

/// The most bytes read_file_bytes() reads from one file unless told otherwise: 4 GiB, beyond
/// any scene, mesh or texture hikari is meant for.
inline constexpr std::uintmax_t k_max_input_bytes = std::uintmax_t{4} << 30;

/// The whole content of `path` as bytes. Only regular files are read: a directory, device
/// (/dev/zero), FIFO or socket is refused at once, before it is opened (a FIFO would block, a
/// device never end). Throws InputError ("PATH: cannot read: REASON") when the file is missing,
/// unreadable, not a regular file, or longer than `max_bytes` (checked as bytes arrive too, for
/// files that grow while read).
std::string read_file_bytes(const std::filesystem::path& path,
                            std::uintmax_t max_bytes = k_max_input_bytes);

/// The same, bounded by the limit of `kind` (input_limits.h); a longer file is refused with
/// "PATH: cannot read: larger than the limit of N MiB for a KIND file (raise it with
/// --max-input-size)".
std::string read_file_bytes(const std::filesystem::path& path, InputKind kind);

/// What a loader can tell of its format before the whole file is read, so a file that is not of
/// the format, or one that the memory budget cannot hold, is refused from its first bytes.
struct FileFormatCheck {
    /// Bytes the loader holds per byte of the file while it parses (the file's text included).
    double memory_per_byte = 1;
    /// What the memory is for in the --max-memory message ("reading an OBJ file").
    std::string_view what = "reading";
    /// Called with the first (up to) k_file_head_bytes bytes and the file's size before the
    /// rest is read; throws InputError for a file that is not of the format.
    std::function<void(std::string_view head, std::uintmax_t size)> check_head;
};

/// How many bytes of a file FileFormatCheck::check_head sees.
inline constexpr size_t k_file_head_bytes = 64;

/// read_file_bytes(path, kind), first checking the file's size against the memory budget
/// (times `check.memory_per_byte`) and its first bytes with `check.check_head`.
std::string read_file_bytes(const std::filesystem::path& path, InputKind kind,
                            const FileFormatCheck& check);

}  // namespace hikari
