#pragma once
// What the two workbook writers share: libxlsxwriter writes only to files, so a workbook is
// built in a temporary file beside its output, checked call by call, and read back as bytes.

#include <xlsxwriter.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace hikari {

/// The bytes of a workbook that `fill` writes the sheets of. libxlsxwriter writes only to files:
/// the workbook is built in a temporary beside `output`, named and removed as every other
/// temporary (io/files/atomic_file.h: also on SIGINT / SIGTERM), with libxlsxwriter's scratch
/// files (unlinked as soon as opened) in the same folder, so no other folder needs to exist or
/// have room; then closed, read back and removed.
std::vector<uint8_t> build_workbook(const std::filesystem::path& output,
                                    const std::function<void(lxw_workbook*)>& fill);

/// Throws InputError "cannot write PATH: WHY".
[[noreturn]] void fail_workbook(const std::filesystem::path& path, const std::string& why);

/// fail_workbook with libxlsxwriter's words unless `error` is LXW_NO_ERROR.
void check_workbook(lxw_error error, const std::filesystem::path& path);

}  // namespace hikari
