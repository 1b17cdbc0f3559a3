#pragma once
// Reading an input file into memory, with an error that names the file and the OS reason.

#include <cstdint>
#include <filesystem>
#include <string>

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

}  // namespace hikari
