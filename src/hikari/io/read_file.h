#pragma once
// Reading an input file into memory, with an error that names the file and the OS reason.

#include <filesystem>
#include <string>

namespace hikari {

/// The whole content of `path` as bytes. Throws InputError ("PATH: cannot read: REASON") when
/// the file is missing, unreadable or a directory.
std::string read_file_bytes(const std::filesystem::path& path);

}  // namespace hikari
